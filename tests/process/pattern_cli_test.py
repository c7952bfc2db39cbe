#!/usr/bin/env python3
"""`nckit pattern` from outside: the example's report (JSON keys, order never worse than drawing
order and within 10 % of the lower bound), the program runs through `nckit plan` (same cycle
time) and `nckit steps`, every size of the series into folders, the mirror, a DXF outline and a
DXF motif giving the same grooves as the CSV and TOML ones, and bad jobs exiting 2 with
FILE:LINE:COL and nothing written.

With --linuxcnc RS274 it instead checks the program against LinuxCNC's rs274 through
tests/programs/compare_linuxcnc.py."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

nckit, root = sys.argv[1], sys.argv[2]
example = os.path.join(root, "examples/pattern")
job = os.path.join(example, "sole_pattern.toml")
machine = os.path.join(example, "stepper_mill.toml")
located = re.compile(r"^[^:\n]+:\d+:\d+: error: ", re.M)


def run(*args):
    return subprocess.run([nckit, *args], capture_output=True, text=True)


def pattern(*args):
    r = run("pattern", *args, "--machine", machine, "--json")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def outline_points():
    points = []
    with open(os.path.join(example, "sole_outline.csv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("x_mm"):
                continue
            x, y = line.strip().split(",")
            points.append((float(x), float(y)))
    return points


def dxf(entities):
    return "0\nSECTION\n2\nENTITIES\n" + "".join(entities) + "0\nENDSEC\n0\nEOF\n"


def dxf_polyline(points):
    out = "0\nPOLYLINE\n8\n0\n66\n1\n70\n1\n10\n0.0\n20\n0.0\n30\n0.0\n"
    for x, y in points:
        out += f"0\nVERTEX\n8\n0\n10\n{x}\n20\n{y}\n30\n0.0\n"
    return out + "0\nSEQEND\n"


def linuxcnc(rs274):
    compare = os.path.join(root, "tests/programs/compare_linuxcnc.py")
    rs274 = shutil.which(rs274) or rs274
    with tempfile.TemporaryDirectory() as tmp:
        for size, extra in (("40", []), ("44", ["--mirror"])):
            nc = os.path.join(tmp, "program.nc")
            r = run("pattern", job, "--machine", machine, "--size", size, *extra, "-o", nc)
            assert r.returncode == 0, r.stderr
            name = os.path.join(tmp, f"0{len(os.listdir(tmp))}_sole_{size}.ngc")
            with open(nc) as f, open(name, "w") as out:
                out.write("( nckit-machine: stepper_mill.toml )\n" + f.read())
            os.remove(nc)
        r = subprocess.run([sys.executable, compare, "--nckit", nckit, "--rs274", rs274, "--programs", tmp,
                            "--machines", example], capture_output=True, text=True)
        print(r.stdout[-3000:], r.stderr[-3000:])
        assert r.returncode == 0, "rs274 and nckit differ"


if len(sys.argv) > 4 and sys.argv[3] == "--linuxcnc":
    linuxcnc(sys.argv[4])
    sys.exit(0)

with tempfile.TemporaryDirectory() as tmp:
    nc, svg = os.path.join(tmp, "sole.nc"), os.path.join(tmp, "sole.svg")
    report = pattern(job, "--size", "40", "-o", nc, "--svg", svg)
    (sole,) = report["sizes"]
    for key in ("size", "mirror", "scale", "cuts", "cut_length_mm", "drawing_order", "optimised_order", "bound",
                "gap_to_bound", "planned", "program", "svg"):
        assert key in sole, key
    for order in ("drawing_order", "optimised_order"):
        assert set(sole[order]) == {"air_distance_mm", "air_time_s", "reversals", "reversal_time_s"}
    drawn, best, bound = sole["drawing_order"], sole["optimised_order"], sole["bound"]
    assert best["air_time_s"] + best["reversal_time_s"] <= drawn["air_time_s"] + drawn["reversal_time_s"]
    assert bound["air_time_s"] <= best["air_time_s"] and bound["air_distance_mm"] <= best["air_distance_mm"]
    assert sole["gap_to_bound"]["air_time"] < 0.10, sole["gap_to_bound"]
    assert sole["cuts"] > 100 and sole["scale"] == {"length": 1, "width": 1}

    # nckit plan gives the cycle time the report planned; nckit steps runs it.
    r = run("plan", nc, "--machine", machine, "--json")
    assert r.returncode == 0, r.stderr
    assert abs(json.loads(r.stdout)["cycle_time_s"] - sole["planned"]["cycle_time_s"]) < 1e-6
    r = run("steps", nc, "--machine", machine, "-o", os.path.join(tmp, "sole.steps"))
    assert r.returncode == 0, r.stderr
    text = open(svg).read()
    assert text.startswith("<svg") and "stroke-dasharray" in text and "<circle" in text
    assert text.count("stroke-linecap") == sole["cuts"]

    # Every size into folders, one program and one drawing each.
    report = pattern(job, "-o", os.path.join(tmp, "nc"), "--svg-dir", os.path.join(tmp, "svg"))
    sizes = {s["size"]: s for s in report["sizes"]}
    assert sorted(sizes) == [38, 39, 40, 41, 42, 44]
    assert sorted(os.listdir(os.path.join(tmp, "nc"))) == sorted(f"sole_pattern_{s}.nc" for s in sizes)
    assert sorted(os.listdir(os.path.join(tmp, "svg"))) == sorted(f"sole_pattern_{s}.svg" for s in sizes)
    assert all(s["svg"] == os.path.join(tmp, "svg", f"sole_pattern_{k}.svg") for k, s in sizes.items())

    # --svg and --html name one file on every verb: with every size of a series they are refused,
    # and nothing is written.
    for option in ("--svg", "--html"):
        target = os.path.join(tmp, "every_size" + option.replace("--", "."))
        r = run("pattern", job, "--machine", machine, option, target)
        assert r.returncode == 2 and f"{option} names one file" in r.stderr and f"{option}-dir" in r.stderr, r.stderr
        assert not os.path.exists(target)
    assert sizes[44]["scale"] == {"length": 1.1, "width": 1.1}
    assert abs(sizes[41]["scale"]["length"] - (260 + 6.667) / 260) < 2e-3
    assert sizes[38]["cuts"] < sizes[40]["cuts"] < sizes[44]["cuts"]

    mirrored = pattern(job, "--size", "40", "--mirror")["sizes"][0]
    assert mirrored["mirror"] is True and mirrored["cuts"] == sole["cuts"]
    assert abs(mirrored["cut_length_mm"] - sole["cut_length_mm"]) < 1e-6

    # The same outline as a DXF polyline, and the same motif as DXF entities.
    with open(os.path.join(tmp, "sole.dxf"), "w") as f:
        f.write(dxf([dxf_polyline(outline_points())]))
    from_dxf = pattern(job, "--size", "40", "--outline", os.path.join(tmp, "sole.dxf"))["sizes"][0]
    assert from_dxf["cuts"] == sole["cuts"] and abs(from_dxf["cut_length_mm"] - sole["cut_length_mm"]) < 1e-6
    with open(os.path.join(tmp, "motif.dxf"), "w") as f:
        f.write(dxf(["0\nLINE\n8\n0\n10\n-4.0\n20\n-2.0\n30\n0\n11\n0.0\n21\n2.0\n31\n0\n",
                     "0\nLINE\n8\n0\n10\n0.0\n20\n2.0\n30\n0\n11\n4.0\n21\n-2.0\n31\n0\n",
                     "0\nARC\n8\n0\n10\n0.0\n20\n-6.0\n30\n0\n40\n3.0\n50\n30.0\n51\n150.0\n",
                     "0\nSPLINE\n8\n0\n70\n8\n71\n3\n72\n0\n73\n0\n74\n5\n"
                     + "".join(f"11\n{x}\n21\n{y}\n31\n0.0\n"
                               for x, y in ((-5.0, 4.0), (-2.5, 5.0), (0.0, 4.0), (2.5, 3.0), (5.0, 4.0)))]))
    shutil.copy(os.path.join(example, "sole_outline.csv"), tmp)
    text = open(job).read()
    text = re.sub(r"\[motif\]\n(.*\n)*?\n", '[motif]\ndxf = "motif.dxf"\n\n', text, count=1)
    with open(os.path.join(tmp, "dxf_motif.toml"), "w") as f:
        f.write(text)
    from_dxf = pattern(os.path.join(tmp, "dxf_motif.toml"), "--size", "40")["sizes"][0]
    assert from_dxf["cuts"] == sole["cuts"], (from_dxf["cuts"], sole["cuts"])
    assert abs(from_dxf["cut_length_mm"] - sole["cut_length_mm"]) < 1e-6

    example_dxf = pattern(os.path.join(example, "sole_pattern_dxf_motif.toml"), "--size", "40")["sizes"][0]
    assert example_dxf["cuts"] == sole["cuts"] and abs(example_dxf["cut_length_mm"] - sole["cut_length_mm"]) < 1e-6

    # Bad input: located error, exit 2, nothing written.
    def bad(args, where, message):
        out = os.path.join(tmp, "bad.nc")
        r = run("pattern", *args, "--machine", machine, "-o", out, "--svg", os.path.join(tmp, "bad.svg"))
        assert r.returncode == 2, (args, r.returncode, r.stderr)
        assert located.search(r.stderr), r.stderr
        assert where in r.stderr and message in r.stderr, r.stderr
        assert not os.path.exists(out) and not os.path.exists(os.path.join(tmp, "bad.svg"))

    with open(os.path.join(tmp, "bow.csv"), "w") as f:
        f.write("x_mm,y_mm\n0,0\n100,40\n200,0\n200,40\n100,0\n0,40\n")
    bad([job, "--outline", os.path.join(tmp, "bow.csv"), "--size", "40"], "bow.csv:", "crosses itself")
    with open(os.path.join(tmp, "typo.csv"), "w") as f:
        f.write("x_mm,y_mm\n0,0\n10,zero\n")
    bad([job, "--outline", os.path.join(tmp, "typo.csv")], "typo.csv:3:", "y_mm is not a number")
    bad([job, "--size", "50"], "sole_pattern.toml:", "size 50 is not in the series")
    for name, old, new, message in (
            ("big_motif", "[[-4.0, -2.0, 0.0, 2.0]", "[[-400.0, -2.0, 0.0, 2.0]", "larger than the sole"),
            ("no_factor", "size = 38\nlength_mm = -13.334\nwidth_mm = -4.4", "size = 38", "size 38 has no factor"),
            ("unknown_key", "depth_mm = 1.0 ", "dept_mm = 1.0 ", "dept_mm")):
        text = open(job).read()
        assert old in text, old
        path = os.path.join(tmp, name + ".toml")
        with open(path, "w") as f:
            f.write(text.replace(old, new))
        bad([path, "--size", "40"], name + ".toml:", message)
print("pattern cli: ok")
