#!/usr/bin/env python3
"""`nckit eccentric` on the example: the JSON contract, the worked cam, a slide limited by its
acceleration, the servo's lag without feedforward, the cam table, the --program output read back
by `nckit moves` on the example Fanuc lathe (X on the cam at every degree, each block one degree
of the turn), and a bad job exiting 2."""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile

nckit, root = sys.argv[1], sys.argv[2]
job = os.path.join(root, "examples/eccentric/eccentric_cam.toml")
lathe = os.path.join(root, "examples/machines/lathe.toml")


def run(*args):
    return subprocess.run([nckit, *args], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    table = os.path.join(tmp, "cam.csv")
    r = run("eccentric", job, "--machine", lathe, "--json", "--cam-table", table)
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    for key in ("roundness_um", "center_offset_um", "max_rpm"):
        assert isinstance(report[key], (int, float)), key
    assert report["roundness_um"] < 1 and report["center_offset_um"] < 1, report
    # e(1 + e/r) = 3.45 mm/rad²: 500 mm/s² allows sqrt(500 / 3.45) rad/s = 114.96 rpm.
    assert abs(report["max_rpm"] - 114.96) < 0.01 and report["limited_by"] == "acceleration", report
    assert report["servo_axis"] is True
    assert report["uncompensated"]["center_offset_um"] > 100, report["uncompensated"]
    assert report["x_diameter_mm"] == {"min": 34, "max": 46}
    with open(table) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 360 and float(rows[0]["x_diameter_mm"]) == 46.0
    assert abs(float(rows[90]["x_diameter_mm"]) - 39.547440) < 1e-6

    # --program: one block a degree after a two-turn G32 lead-in from the index, read back on
    # the example lathe (system A, feed per revolution).
    program = os.path.join(tmp, "eccentric.nc")
    r = run("eccentric", job, "--machine", lathe, "--program", program)
    assert r.returncode == 0, r.stderr
    r = run("moves", program, "--machine", lathe, "--json")
    assert r.returncode == 0 and r.stderr == "", r.stderr
    records = [json.loads(line) for line in r.stdout.splitlines() if line.strip()]
    sync = [m for m in records if m["kind"] == "sync"]
    blocks = [m for m in records if m["kind"] == "linear"]
    assert len(sync) == 1 and sync[0]["feed_mm_rev"] == 0.1 and sync[0]["end"]["Z"] == 0.0, sync
    assert sync[0]["end"]["X"] == 23.0  # radius e + r at theta 0
    assert len(blocks) == 300 * 360, len(blocks)  # 30 mm at 0.1 mm/rev, one block a degree
    # X (a radius here) on the cam a(theta) = e cos theta + sqrt(r^2 - e^2 sin^2 theta) at whole turns
    # and quarter turns: the worked values of docs/processes/eccentric.md.
    for k, radius in ((90, 19.77372), (180, 17.0), (270, 19.77372), (360, 23.0), (360 * 150 + 90, 19.77372)):
        assert abs(blocks[k - 1]["end"]["X"] - radius) < 1e-5, (k, blocks[k - 1]["end"])
    for k in (1, 45, 1000, 54321):
        e_, r_, t = 3.0, 20.0, math.radians(k)
        a = e_ * math.cos(t) + math.sqrt(r_ * r_ - e_ * e_ * math.sin(t) ** 2)
        assert abs(blocks[k - 1]["end"]["X"] - a) < 1e-5 and abs(blocks[k - 1]["end"]["Z"] + 0.1 * k / 360) < 1e-5
    # Each block lasts one degree of the turn: its path (X as a radius) over its feed per
    # revolution is 1/360; the pass is 300 turns.
    turns = [math.hypot(m["end"]["X"] - m["start"]["X"], m["end"]["Z"] - m["start"]["Z"]) / m["feed_mm_rev"]
             for m in blocks]
    assert max(abs(t - 1 / 360) for t in turns) < 1e-8, max(abs(t - 1 / 360) for t in turns)
    assert abs(sum(turns) - 300) < 1e-6, sum(turns)
    assert blocks[-1]["end"]["Z"] == -30.0

    bad = os.path.join(tmp, "bad.toml")
    with open(bad, "w") as f:
        f.write("[eccentric]\nblank_diameter_mm = 60.0\neccentricity_mm = 3.0\neccentric_radius_mm = 20.0\n"
                "z_start_mm = 0.0\nz_end_mm = -30.0\nrpm = 400\nfeed_mm_rev = 0.1\n")
    r = run("eccentric", bad, "--machine", lathe, "--cam-table", os.path.join(tmp, "never.csv"))
    assert r.returncode == 2, r.returncode
    assert re.search(r"bad\.toml:7:7: error: at 400 rpm the X axis would need .* up to 115 rpm", r.stderr), r.stderr
    assert not os.path.exists(os.path.join(tmp, "never.csv"))
    # A program of more than two million blocks: exit 2 at feed_mm_rev, nothing written.
    with open(job) as f:
        good_text = f.read()
    fine = os.path.join(tmp, "fine.toml")
    with open(fine, "w") as f:
        f.write(good_text.replace("feed_mm_rev = 0.1", "feed_mm_rev = 0.001"))
    line = next(i for i, text in enumerate(good_text.splitlines(), 1) if text.startswith("feed_mm_rev"))
    r = run("eccentric", fine, "--machine", lathe, "--program", os.path.join(tmp, "never.nc"),
            "--cam-table", os.path.join(tmp, "never2.csv"))
    assert r.returncode == 2 and re.search(rf"fine\.toml:{line}:15: error: --program: 30000 turns", r.stderr), r.stderr
    assert not os.path.exists(os.path.join(tmp, "never.nc")) and not os.path.exists(os.path.join(tmp, "never2.csv"))
    # A lead-in of two turns below the program's 0.00001 mm: exit 2 at feed_mm_rev.
    with open(fine, "w") as f:
        f.write(good_text.replace("feed_mm_rev = 0.1", "feed_mm_rev = 0.000001").replace("z_end_mm = -30.0",
                                                                                        "z_end_mm = -0.001"))
    r = run("eccentric", fine, "--machine", lathe, "--program", os.path.join(tmp, "never.nc"))
    assert r.returncode == 2 and re.search(rf"fine\.toml:{line}:15: error: --program: two turns", r.stderr), r.stderr
    assert not os.path.exists(os.path.join(tmp, "never.nc"))

    # Fuzz findings: fewer than 3 updates a turn cannot fit a circle (it reported an offset of
    # 1.8e20 um and roundness 0); a speed above the highest within 1 um is an error, not exit 0.
    with open(job) as f:
        good = f.read()
    few = os.path.join(tmp, "few.toml")
    with open(few, "w") as f:
        f.write(good.replace("rpm = 60\n", "rpm = 60\nupdates_per_turn = 2\n"))
    r = run("eccentric", few, "--machine", lathe)
    assert r.returncode == 2 and "at least 3 points a turn" in r.stderr, (r.returncode, r.stderr)
    following_limit = report["max_rpm_by"]["following"]
    if following_limit is not None and following_limit < report["max_rpm_by"]["acceleration"]:
        fast = os.path.join(tmp, "fast.toml")
        with open(fast, "w") as f:
            f.write(good.replace("rpm = 60\n", f"rpm = {following_limit * 1.05:.3f}\n"))
        r = run("eccentric", fast, "--machine", lathe)
        assert r.returncode == 2 and "within 1 um" in r.stderr, (r.returncode, r.stderr)
print("ok")
