#!/usr/bin/env python3
"""`nckit piston` on the two example jobs: the JSON contract and the goal (learning within 1 µm
peak to valley, better than feedforward, better than nothing); the cam table's rows and header;
the trace, re-simulated here through the true servo (k = 1, the job's f_n and zeta, exact
zero-order hold over each row's own interval) from its first row, which must reproduce every
actual_mm; the SVG plots parse as XML; the --program output read back by `nckit moves` and
`nckit plan` on the example Fanuc lathe (feed per revolution, X on the middle of the cam table's
radial range at every station, the cut timed from the spindle speed); bad jobs exit 2 with
FILE:LINE:COL and write nothing."""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

nckit, root = sys.argv[1], sys.argv[2]
examples = os.path.join(root, "examples/piston")
lathe = os.path.join(root, "examples/machines/lathe.toml")

CAM_HEADER = ["z_mm", "phi_deg", "radius_mm"]
TRACE_HEADER = ["t_s", "theta_deg", "z_mm", "radius_mm", "target_mm", "command_mm", "actual_mm", "actual_mm_s"]


def run(*args):
    return subprocess.run([nckit, "piston", *args], capture_output=True, text=True)


def read_servo(job_path):
    """natural_frequency_hz and damping of the job's [servo] table (flat keys, no toml module needed)."""
    values, table = {}, None
    with open(job_path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line.startswith("["):
                table = line
            elif table == "[servo]" and "=" in line:
                key, value = (part.strip() for part in line.split("=", 1))
                values[key] = float(value)
    return values["natural_frequency_hz"], values["damping"]


def expm2(a, h):
    """exp(a h) of a 3x3 matrix (list of rows) by scaling and squaring a Taylor series."""
    m = [[x * h for x in row] for row in a]
    norm = max(sum(abs(x) for x in row) for row in m)
    squarings = max(0, math.ceil(math.log2(norm / 0.25))) if norm > 0.25 else 0
    scale = 2.0 ** -squarings
    m = [[x * scale for x in row] for row in m]
    n = len(m)
    result = [[float(i == j) for j in range(n)] for i in range(n)]
    term = [row[:] for row in result]
    for k in range(1, 20):
        term = [[sum(term[i][l] * m[l][j] for l in range(n)) / k for j in range(n)] for i in range(n)]
        result = [[result[i][j] + term[i][j] for j in range(n)] for i in range(n)]
    for _ in range(squarings):
        result = [[sum(result[i][l] * result[l][j] for l in range(n)) for j in range(n)] for i in range(n)]
    return result


def resimulate(rows, natural_frequency_hz, damping):
    """Largest |predicted - traced| actual_mm over the trace. The state is (y, v / wn) so the
    matrix is balanced; the input u enters as a third, constant state (zero-order hold)."""
    wn = 2 * math.pi * natural_frequency_hz
    a = [[0.0, wn, 0.0], [-wn, -2 * damping * wn, wn], [0.0, 0.0, 0.0]]
    y, w = rows[0]["actual_mm"], rows[0]["actual_mm_s"] / wn
    worst = 0.0
    for row, following in zip(rows, rows[1:]):
        e = expm2(a, following["t_s"] - row["t_s"])
        u = row["command_mm"]
        y, w = (e[0][0] * y + e[0][1] * w + e[0][2] * u, e[1][0] * y + e[1][1] * w + e[1][2] * u)
        worst = max(worst, abs(y - following["actual_mm"]))
    return worst


def check_json(report):
    errors = report["profile_error_um"]
    assert set(errors) >= {"uncompensated", "feedforward", "learning"}, errors
    for run_name in ("uncompensated", "feedforward", "learning"):
        assert set(errors[run_name]) >= {"pv", "rms"}, errors[run_name]
        assert 0 < errors[run_name]["rms"] <= errors[run_name]["pv"], errors[run_name]
    learning, feedforward, none = (errors[k]["pv"] for k in ("learning", "feedforward", "uncompensated"))
    assert learning <= 1.0 < feedforward < none, errors  # the goal of the issue
    assert errors["learning"]["rms"] < errors["feedforward"]["rms"] < errors["uncompensated"]["rms"]
    for key in ("rpm", "tick_rate_hz", "dac_step_mm", "cam_table", "learning", "servo_demand", "duration_s",
                "model_error", "spindle_ripple"):
        assert key in report, key
    assert report["rpm"] == 2500 and report["tick_rate_hz"] == 15000 and report["model_error"] == 0.1
    assert abs(report["dac_step_mm"] - 1.0 / 65536) < 1e-15
    table = report["cam_table"]
    assert table["error_bound_mm"] <= table["tolerance_mm"] == 1e-6, table
    assert table["cells"] == table["theta_cells"] * table["z_cells"] > 0
    demand = report["servo_demand"]
    # The stroke is centred: the oval's 0.4 mm radial range swings +-0.2 mm about mid-stroke.
    assert abs(demand["peak_displacement_mm"] - 0.2) < 1e-6, demand
    assert demand["peak_displacement_mm"] < demand["displacement_limit_mm"] < 0.5
    assert demand["acceleration_mm_s2"] < demand["acceleration_limit_mm_s2"]
    assert 0 <= report["learning"]["settled_turn"] < 520
    # 50 mm at 0.1 mm/rev after 20 air turns: 520 turns of 360 counts, the closing tick included.
    assert report["ticks"] == 520 * 360 + 1 and abs(report["duration_s"] - 520 * 60 / 2500) < 0.05


with tempfile.TemporaryDirectory() as tmp:
    for name in ("piston.toml", "piston_formula.toml"):
        job = os.path.join(examples, name)
        cam, trace, svg = (os.path.join(tmp, f"{name}.{ext}") for ext in ("cam.csv", "trace.csv", "svg"))
        turns = 2 if name == "piston.toml" else 3
        extra = ["--trace-turns", str(turns)] if turns != 3 else []  # 3 is the default
        r = run(job, "--json", "--svg-dir", svg, "--cam-table", cam, "--trace", trace, *extra)
        assert r.returncode == 0, r.stderr
        report = json.loads(r.stdout)
        check_json(report)
        assert report["spindle_ripple"] == 0.002  # the jobs leave it out: the simulation's default

        with open(cam) as f:
            rows = list(csv.reader(f))
        assert rows[0] == CAM_HEADER, rows[0]
        assert len(rows) - 1 == 6 * 360, len(rows)
        assert [int(r[1]) for r in rows[1:361]] == list(range(360))
        assert sorted({float(r[0]) for r in rows[1:]}) == [0, 10, 20, 30, 40, 50]
        by_angle = {int(r[1]): float(r[2]) for r in rows[1:361]}  # Z 0: D 89.8, E 0.4
        if name == "piston.toml":
            assert abs(by_angle[0] - 44.9) < 1e-6 and abs(by_angle[90] - 44.7) < 1e-6, (by_angle[0], by_angle[90])

        with open(trace) as f:
            reader = csv.reader(f)
            header = next(reader)
            rows = [dict(zip(header, map(float, line))) for line in reader]
        assert header == TRACE_HEADER, header
        assert abs(len(rows) - turns * 360) <= 1, len(rows)
        assert rows[-1]["z_mm"] == 50.0
        assert all(abs(r["target_mm"]) <= 0.2 + 1e-9 for r in rows)
        assert max(abs(r["actual_mm"] - r["target_mm"]) for r in rows) < 1e-3  # learnt: within 1 µm
        worst = resimulate(rows, *read_servo(job))
        assert worst < 1e-6, worst

        for plot in ("section.svg", "drawing.svg", "turn_error.svg"):
            tree = ElementTree.parse(os.path.join(svg, plot))
            assert tree.getroot().tag == "{http://www.w3.org/2000/svg}svg", plot
            drawing = open(os.path.join(svg, plot)).read()
            assert "<polyline" in drawing, plot
        section = open(os.path.join(svg, "section.svg")).read()
        assert re.search(r"magnified ×\d", section) and "major axis" in section and "minor axis" in section
        assert section.count("<polyline") == 6  # one section per station
        assert open(os.path.join(svg, "drawing.svg")).read().count("<circle") == 2 * 6  # D and E at the stations

    # --program: the slide's path as a Fanuc lathe program, read back on the example lathe
    # (system A, feed per revolution at power-up). X is the middle of each turn's radial range;
    # at the stations that is (max + min) / 2 of the cam table's rows, every degree.
    job = os.path.join(examples, "piston.toml")
    program, cam = os.path.join(tmp, "piston.nc"), os.path.join(tmp, "program_cam.csv")
    r = run(job, "--program", program, "--cam-table", cam)
    assert r.returncode == 0, r.stderr
    moves = subprocess.run([nckit, "moves", program, "--machine", lathe, "--json"], capture_output=True, text=True)
    assert moves.returncode == 0 and moves.stderr == "", moves.stderr
    records = [json.loads(line) for line in moves.stdout.splitlines() if line.strip()]
    feeds = [m for m in records if m["kind"] == "linear"]
    assert len(feeds) == 101, len(feeds)  # onto the crown, then every 0.5 mm to Z-50
    assert all(m["feed_mm_rev"] == 0.1 and abs(m["feed_mm_min"] - 250.0) < 1e-9 for m in feeds), feeds[0]
    assert feeds[0]["end"]["Z"] == 0.0 and feeds[-1]["end"]["Z"] == -50.0
    dwells = [m for m in records if m["kind"] == "dwell"]
    assert len(dwells) == 1 and abs(dwells[0]["seconds"] - 20 * 60 / 2500) < 1e-9, dwells
    with open(cam) as f:
        rows = list(csv.reader(f))[1:]
    slide = {round(-m["end"]["Z"], 6): m["end"]["X"] for m in feeds}  # radius, mm
    for z in (0, 10, 20, 30, 40, 50):
        turn = [float(row[2]) for row in rows if float(row[0]) == z]
        middle = (max(turn) + min(turn)) / 2
        assert abs(slide[z] - middle) < 2e-5, (z, slide[z], middle)
    plan = subprocess.run([nckit, "plan", program, "--machine", lathe, "--json"], capture_output=True, text=True)
    assert plan.returncode == 0, plan.stderr
    # 51 mm at 0.1 mm/rev x 2500 rpm = 250 mm/min is 12.24 s, with the 0.48 s wait and the rapids.
    cycle = json.loads(plan.stdout)["cycle_time_s"]
    assert 12.72 <= cycle <= 16.0, cycle

    # The text report names the three runs.
    r = run(os.path.join(examples, "piston.toml"))
    assert r.returncode == 0 and all(k in r.stdout for k in ("uncompensated", "feedforward", "learning")), r.stdout

    # A job's own spindle_ripple is used as given, 0 included.
    with open(os.path.join(examples, "piston.toml")) as f:
        text = f.read()
    steady = os.path.join(tmp, "steady.toml")
    with open(steady, "w") as f:
        f.write(text.replace("[servo]", "spindle_ripple = 0.0\n[servo]"))
    r = run(steady, "--json")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["spindle_ripple"] == 0
    check_json(json.loads(r.stdout))

    # Bad jobs: exit 2, FILE:LINE:COL at the key at fault, no output of any kind.
    with open(os.path.join(examples, "piston_formula.toml")) as f:
        formula_text = f.read()
    bad_jobs = {
        "formula.toml": (formula_text.replace("(Z - 30)^2\"", "(Z - 30\""),
                         r"formula\.toml:8:44: error: formula syntax in 'major_diameter_mm'"),
        # The oval's 0.4 mm radial range in a 0.3 mm stroke: the job reader refuses it.
        "stroke.toml": (text.replace("stroke_mm = 1.0", "stroke_mm = 0.3"),
                        r"stroke\.toml:8:14: error: the profile needs 0\.4000 mm of stroke"),
        # Exactly the range: the DAC's top code is one step short of +stroke/2.
        "stroke_edge.toml": (text.replace("stroke_mm = 1.0", "stroke_mm = 0.4"),
                             r"stroke_edge\.toml:14:13: error: the profile swings 0\.200000 mm"),
        "encoder.toml": (formula_text.replace("encoder_counts = 360", "encoder_counts = 4"),
                         r"encoder\.toml:11:18: error: the fast tool servo needs at least 8 encoder counts"),
    }
    for name, (content, message) in bad_jobs.items():
        bad = os.path.join(tmp, name)
        with open(bad, "w") as f:
            f.write(content)
        out = os.path.join(tmp, "never")
        r = run(bad, "--json", "--svg-dir", out + "_svg", "--cam-table", out + ".csv", "--trace", out + "_trace.csv",
                "--program", out + ".nc")
        assert r.returncode == 2, (name, r.returncode, r.stdout)
        assert re.search(message, r.stderr), (name, r.stderr)
        assert r.stdout == "", r.stdout
        leftovers = [p for p in os.listdir(tmp) if p.startswith("never")]
        assert not leftovers, leftovers
    r = run(os.path.join(tmp, "missing.toml"))
    assert r.returncode == 2 and "missing.toml:0:0: error: cannot read piston job" in r.stderr, r.stderr
    r = run(os.path.join(examples, "piston.toml"), "--trace-turns", "2")  # needs --trace
    assert r.returncode == 2, r.returncode
print("ok")
