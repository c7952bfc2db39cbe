#!/usr/bin/env python3
"""`nckit notch` on the conrod example: JSON keys and figures, the rewritten program runs clean
through `nckit moves` and `nckit plan`, and a refused run-up exits 2 with FILE:LINE:COL."""
import json
import os
import re
import subprocess
import sys
import tempfile

nckit, root = sys.argv[1], sys.argv[2]
program = os.path.join(root, "examples/notch/conrod.nc")
machine = os.path.join(root, "examples/machines/notcher.toml")


def run(*args):
    return subprocess.run([nckit, *args], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "conrod_notched.nc")
    r = run("notch", program, "--machine", machine, "--json", "-o", out)
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    assert len(report["cuts"]) == 1, report
    cut = report["cuts"][0]
    for key in ("line", "run_up_mm", "feed_mm_min", "before", "after"):
        assert key in cut, key
    for side in ("before", "after"):
        for key in ("min_mm_min", "max_mm_min", "mean_mm_min", "profile"):
            assert key in cut[side], (side, key)
        assert all(len(p) == 2 for p in cut[side]["profile"])
    assert cut["line"] == 9, cut["line"]
    assert abs(cut["run_up_mm"] - 0.890991) < 5e-7, cut["run_up_mm"]
    assert cut["feed_mm_min"] == 950
    assert cut["before"]["min_mm_min"] < 1.0, cut["before"]
    assert abs(cut["after"]["min_mm_min"] / 950 - 1) <= 1e-3, cut["after"]["min_mm_min"]
    assert abs(cut["after"]["max_mm_min"] / 950 - 1) <= 1e-3, cut["after"]["max_mm_min"]
    for verb in ("moves", "plan"):
        r = run(verb, out, "--machine", machine)
        assert r.returncode == 0, (verb, r.stderr)

    # An oblique cut: the written run-up and overrun points lie exactly on the cut line (the
    # cross product of the decimals as written is 0, in exact fractions), and the head crosses
    # the whole cut at F.
    oblique = os.path.join(tmp, "oblique.nc")
    with open(oblique, "w") as f:
        f.write("G1 G90 X68.5 Z-10 F3000\nM24\nG1 X70 Z-15.53 F5000\nM27\nG1 X73.1234 Z-33.63 F950\n"
                "G1 X80 F3000\nM25\nM30\n")
    oblique_out = os.path.join(tmp, "oblique_notched.nc")
    r = run("notch", oblique, "--machine", machine, "--json", "-o", oblique_out)
    assert r.returncode == 0, r.stderr
    cut = json.loads(r.stdout)["cuts"][0]
    assert abs(cut["after"]["min_mm_min"] / 950 - 1) <= 1e-3, cut["after"]
    from fractions import Fraction
    points = [tuple(Fraction(v) for v in re.search(r"X(-?[\d.]+) Z(-?[\d.]+)", line).groups())
              for line in open(oblique_out) if re.match(r"(G61 )?G[01] X", line)]
    start, end = (Fraction(70), Fraction("-15.53")), (Fraction("73.1234"), Fraction("-33.63"))
    i = points.index(end) - 1
    run_up, overrun = points[i - 1], points[i + 2]
    assert points[i] == start, points
    for p, q in ((run_up, start), (end, overrun)):
        cross = (q[0] - p[0]) * (end[1] - start[1]) - (q[1] - p[1]) * (end[0] - start[0])
        assert cross == 0, (p, q, cross)

    bad = os.path.join(tmp, "bad.nc")
    with open(bad, "w") as f:
        f.write("G1 X10 Z99.5 F3000\nM27\nG1 Z80 F950\nG1 X20\nM30\n")
    r = run("notch", bad, "--machine", machine, "-o", os.path.join(tmp, "never.nc"))
    assert r.returncode == 2, r.returncode
    assert re.search(r"bad\.nc:3:\d+: error: the run-up of 0\.8910 mm .* travel", r.stderr), r.stderr
    assert not os.path.exists(os.path.join(tmp, "never.nc"))
print("ok")
