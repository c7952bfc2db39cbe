#!/usr/bin/env python3
"""The `nckit servo` contract: on examples/machines/servo_mill.toml a long feed at constant speed
settles at the analytic lag 2·zeta·T·v (+ v·h/2 for the held setpoint); the JSON report, the
text report and the trace agree; the duration is `nckit plan`'s cycle time; a bad program, or a
machine without servo axes, writes nothing and exits 2."""
import csv
import json
import math
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
SERVO_MILL = ROOT / "examples" / "machines" / "servo_mill.toml"
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAIL {what}")


def nckit_run(nckit, *args):
    return subprocess.run([nckit, *map(str, args)], capture_output=True, text=True, timeout=120)


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        program = tmp / "feed.ngc"
        # X 0 -> 300 at 6000 mm/min = 100 mm/s: 3 s, nearly all of it at constant speed.
        program.write_text("G21 G90 G17\nG1 X300 F6000\nM30\n")
        trace = tmp / "trace.csv"
        run = nckit_run(nckit, "servo", program, "--machine", SERVO_MILL, "--json", "--trace", trace)
        check(run.returncode == 0, f"--json exits 0 ({run.stderr})")
        report = json.loads(run.stdout)
        check(set(report) >= {"axes", "duration_s"}, f"report keys {sorted(report)}")
        check(list(report["axes"]) == ["X", "Y", "Z"], f"servo axes {list(report['axes'])}")
        for axis in report["axes"].values():
            check(set(axis) == {"max_following_error_mm", "rms_following_error_mm", "t_max_s"}, f"axis keys {axis}")

        plan = json.loads(nckit_run(nckit, "plan", program, "--machine", SERVO_MILL, "--json").stdout)
        check(abs(report["duration_s"] - plan["cycle_time_s"]) < 1e-12, "duration is the plan's cycle time")

        # servo_mill.toml's X: 30 Hz, zeta 0.7, gain 1; samples every 1 ms.
        h, v, zeta = 0.001, 100.0, 0.7
        T = 1 / (2 * math.pi * 30.0)
        lag = 2 * zeta * T * v
        with trace.open() as f:
            rows = list(csv.DictReader(f))
        check(list(rows[0]) == ["t_s", "axis", "setpoint_mm", "actual_mm", "following_error_mm"], "trace columns")
        x = [r for r in rows if r["axis"] == "X"]
        check(len(rows) == 3 * len(x) == 3 * report["samples"], "one row per servo axis per sample")
        check(all(abs(float(r["t_s"]) - k * h) < 1e-12 for k, r in enumerate(x)), "samples every servo period")
        check(float(x[-1]["t_s"]) >= report["duration_s"] - 1e-12, "samples reach the end")
        check(all(abs(float(r["setpoint_mm"]) - float(r["actual_mm"]) - float(r["following_error_mm"])) < 1e-12
                  for r in rows), "following error = setpoint - actual")
        middle = float(x[len(x) // 2]["following_error_mm"])
        check(abs(middle - (lag + v * h / 2)) < 0.01 * v * h, f"steady lag {middle} against {lag} + v h / 2")
        worst = max(x, key=lambda r: abs(float(r["following_error_mm"])))
        check(abs(abs(float(worst["following_error_mm"])) - report["axes"]["X"]["max_following_error_mm"]) < 1e-12,
              "max from the trace")
        check(abs(float(worst["t_s"]) - report["axes"]["X"]["t_max_s"]) < 1e-12, "t_max_s from the trace")
        rms = math.sqrt(sum(float(r["following_error_mm"]) ** 2 for r in x) / len(x))
        check(abs(rms - report["axes"]["X"]["rms_following_error_mm"]) < 1e-9, "rms from the trace")
        check(report["axes"]["Y"]["max_following_error_mm"] == 0, "Y stands still: no error")

        text = nckit_run(nckit, "servo", program, "--machine", SERVO_MILL)
        check(text.returncode == 0 and "X" in text.stdout and "duration" in text.stdout, "text report")
        check(f"{report['axes']['X']['max_following_error_mm']:.6f}" in text.stdout, "text max equals JSON max")

        bad = tmp / "bad.ngc"
        bad.write_text("G1 X10 F100\nG1 X20 Q5\n")
        bad_trace = tmp / "bad.csv"
        run = nckit_run(nckit, "servo", bad, "--machine", SERVO_MILL, "--trace", bad_trace)
        check(run.returncode == 2 and ":2:" in run.stderr, f"a bad program exits 2 at its line ({run.stderr})")
        check(not bad_trace.exists() and not (tmp / "bad.csv.partial").exists(), "a bad program writes nothing")
        run = nckit_run(nckit, "servo", program, "--trace", bad_trace)
        check(run.returncode == 2 and "servo" in run.stderr, "the built-in mill has no servo axis: exit 2")
        check(not bad_trace.exists(), "nothing written without servo axes")
    print(f"{'FAILED' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
