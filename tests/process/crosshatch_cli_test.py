#!/usr/bin/env python3
"""`nckit crosshatch` on the three examples: the JSON contract and the worked numbers of
docs/processes/crosshatch.md; the G-code runs through `nckit moves` and `nckit steps` on the
crosshatch machine and needs exactly the steps of the crosshatch's own step streams; the SVG
draws the tracks; a bad job exits 2 with FILE:LINE:COL and writes nothing."""
import json
import os
import re
import subprocess
import sys
import tempfile
from collections import Counter

nckit, root = sys.argv[1], sys.argv[2]
machine = os.path.join(root, "examples/machines/crosshatch.toml")

# heads, index: rotation rpm, divisor rotation, pattern, index move, crosshatch angle
worked = {
    (12, 30): (2.5, 33333, "arbitrary", -150.0, 45.0952),
    (8, 45): (3.75, 22222, "arbitrary", 135.0, 30.9432),
    (6, 60): (5.0, 16667, "arbitrary", 60.0, 23.4553),
}


def run(*args):
    return subprocess.run([nckit, *args], capture_output=True, text=True)


def steps_per_axis(lines):
    """Steps of each axis, counted per direction, from 't_ns axis dir [port]' lines."""
    counts = Counter()
    for line in lines:
        fields = line.split()
        counts[(int(fields[1]), int(fields[2]))] += 1
    return counts


with tempfile.TemporaryDirectory() as tmp:
    for (heads, index), (rpm, divisor, pattern, move, angle) in worked.items():
        job = os.path.join(root, f"examples/crosshatch/bore_{heads}heads_{index}deg.toml")
        nc, svg, steps = (os.path.join(tmp, f"{heads}.{ext}") for ext in ("nc", "svg", "steps"))
        r = run("crosshatch", job, "--json", "--svg", svg, "-o", nc, "--steps", steps, "--text")
        assert r.returncode == 0, r.stderr
        report = json.loads(r.stdout)
        for key in ("rotation_rpm", "feed_mm_min", "timer_divisor", "speed_error", "pattern", "index_move_deg",
                    "crosshatch_angle_deg", "closure_error_steps"):
            assert key in report, key
        assert set(report["timer_divisor"]) >= {"rotation", "feed"}
        assert set(report["speed_error"]) >= {"rotation", "feed"}
        assert abs(report["rotation_rpm"] - rpm) < 1e-9, report
        assert report["feed_mm_min"] == 300
        assert report["timer_divisor"]["rotation"] == divisor and report["timer_divisor"]["feed"] == 1389
        assert abs(report["speed_error"]["feed"] - (1388.8889 / 1389 - 1)) < 1e-7
        assert report["pattern"] == pattern and report["index_move_deg"] == move, report
        assert abs(report["crosshatch_angle_deg"] - angle) < 5e-5
        assert report["closure_error_steps"] < 1

        # The program moves as the report says: Z strokes of 150 mm, the head back at a whole turn.
        r = run("moves", nc, "--machine", machine, "--json")
        assert r.returncode == 0, r.stderr
        moves = [json.loads(line) for line in r.stdout.splitlines()]
        motion = [m for m in moves if m["kind"] in ("rapid", "linear")]
        assert motion[-1]["end"]["Z"] == 0 and motion[-1]["end"]["A"] % 360 == 0, motion[-1]
        assert sum(1 for m in moves if m.get("code") == "M27") == heads

        # Through the planner and the step generator: the same steps as the crosshatch's own stream.
        r = run("steps", nc, "--machine", machine, "--text")
        assert r.returncode == 0, r.stderr
        planned = steps_per_axis(r.stdout.splitlines())
        with open(steps) as f:
            own_lines = f.read().splitlines()
        own = steps_per_axis(own_lines)
        assert planned == own, (planned, own)
        # Same machine port bytes, step by step, on both routes (the seed's codes on each motor).
        def port_sequences(lines):
            sequences = {0: [], 1: []}
            for line in lines:
                fields = line.split()
                sequences[int(fields[1])].append((fields[2], fields[3]))
            return sequences
        assert port_sequences(r.stdout.splitlines()) == port_sequences(own_lines)
        assert all(re.fullmatch(r"\d+ [01] -?1 0x[0-9A-F]{2}", line) for line in own_lines[:50])
        assert own[(0, -1)] == own[(0, 1)] == 21600 * heads

        with open(svg) as f:
            drawing = f.read()
        assert drawing.startswith("<svg") and drawing.count("<line") > 2 * heads, drawing[:200]

    # Bad jobs: exit 2, FILE:LINE:COL, no output.
    bad = os.path.join(tmp, "bad.toml")
    with open(bad, "w") as f:
        f.write("[crosshatch]\nbore_diameter_mm = 92.0\nbore_length_mm = 150.0\nlead_screw_pitch_mm = 5.0\n"
                "heads = 12\nlines_per_length = 15.0\nfeed_screw_rpm = 0.05\n")
    out = os.path.join(tmp, "never.nc")
    r = run("crosshatch", bad, "-o", out, "--svg", out + ".svg")
    assert r.returncode == 2, r.returncode
    assert re.search(r"bad\.toml:7:18: error: the rotation motor needs .* slower than the counter makes", r.stderr), r.stderr
    assert not os.path.exists(out) and not os.path.exists(out + ".svg")
    r = run("crosshatch", os.path.join(tmp, "missing.toml"))
    assert r.returncode == 2 and "missing.toml:0:0: error: cannot read crosshatch job" in r.stderr, r.stderr
print("ok")
