#!/usr/bin/env python3
"""The `nckit plan` contract: report keys, JSON precision, the trace CSV, options, exit status."""
import json
import pathlib
import sys
import tempfile

from cli_checks import check, run_nckit, summary

ROOT = pathlib.Path(__file__).resolve().parents[2]


def plan(nckit, *args):
    return run_nckit(nckit, "plan", *args, text=True)


def main() -> int:
    nckit = sys.argv[1]
    square = ROOT / "bench" / "planner_programs" / "square_100.ngc"
    run = plan(nckit, square, "--json")
    check(run.returncode == 0, f"plan --json exits 0 ({run.stderr.strip()})")
    report = json.loads(run.stdout)
    check(set(report) >= {"cycle_time_s", "moves", "axes"}, "report keys")
    check(report["moves"] == 4, "moves counted")
    check(set(report["axes"]) == {"X", "Y", "Z"}, "one entry per configured axis")
    for axis, peaks in report["axes"].items():
        check(set(peaks) == {"max_velocity", "max_acceleration", "max_jerk"}, f"{axis} peak keys")
        check(peaks["max_acceleration"] <= 500.0 * (1 + 1e-6), f"{axis} acceleration within the limit")
        check(peaks["max_velocity"] <= 100.0 * (1 + 1e-6), f"{axis} velocity within the limit")
    check(len(repr(report["cycle_time_s"])) > 8, "full double precision")

    trapezoid = json.loads(plan(nckit, square, "--json", "--profile", "trapezoid").stdout)
    check(trapezoid["cycle_time_s"] < report["cycle_time_s"], "the jerk limit makes the S-curve longer")
    slow = json.loads(plan(nckit, square, "--json", "--override", "50").stdout)
    check(slow["cycle_time_s"] > report["cycle_time_s"] * 1.5, "50 % override takes longer")
    check(plan(nckit, square, "--override", "0").returncode == 2, "0 % override is refused")

    with tempfile.TemporaryDirectory() as tmp:
        trace = pathlib.Path(tmp) / "square.csv"
        run = plan(nckit, square, "--trace", trace, "--period", "0.002")
        check(run.returncode == 0 and "cycle time" in run.stdout, "text report")
        rows = trace.read_text().splitlines()
        check(rows[0] == "t,X,Y,Z,vX,vY,vZ,aX,aY,aZ,jX,jY,jZ", "trace header")
        times = [float(r.split(",")[0]) for r in rows[1:]]
        check(abs(times[1] - 0.002) < 1e-12 and times[0] == 0.0, "trace period")
        expected_rows = int(report["cycle_time_s"] / 0.002) + 1
        check(abs(len(times) - expected_rows) <= 1, f"trace covers the cycle ({len(times)} rows, {expected_rows} expected)")
        last = rows[-1].split(",")
        check(abs(float(last[1])) < 1e-3 and abs(float(last[2])) < 1e-3, "trace ends at the program's end point")

        bad = pathlib.Path(tmp) / "bad.ngc"
        bad.write_text("G21 G90\nG0 X5.\nG1 X10.\nM30\n")
        bad_trace = pathlib.Path(tmp) / "bad.csv"
        run = plan(nckit, bad, "--trace", bad_trace)
        check(run.returncode == 2, "a bad program exits 2")
        check("bad.ngc:3:1: error:" in run.stderr, "FILE:LINE:COL error")
        check(not bad_trace.exists() and not pathlib.Path(str(bad_trace) + ".partial").exists(),
              "a bad program leaves no trace file")
        check(run.stdout == "", "a bad program prints no report")

        # Threading: every G32 pass waits for the spindle index; the spindle model, replayed, agrees.
        thread = ROOT / "examples" / "03_lathe_thread.ngc"
        lathe = ROOT / "examples" / "machines" / "lathe.toml"
        run = plan(nckit, thread, "--machine", lathe, "--json")
        check(run.returncode == 0, "the thread example plans")
        sync = json.loads(run.stdout)["spindle_sync"]
        check(sync["starts"] == 4 and len(sync["first"]) == 4, "four thread passes")
        check(sync["max_index_error_deg"] < 1e-6, "every pass starts on the index")
        turn_s = 60 / 600
        check(all(0 <= s["wait_s"] < turn_s for s in sync["first"]), "each wait is under one turn")
        check(all(abs(s["t_s"] * 3600 / 360 - round(s["t_s"] * 3600 / 360)) < 1e-6 for s in sync["first"]),
              "600 rpm from t = 0: each start is a whole number of turns")
        stopped = pathlib.Path(tmp) / "stopped.ngc"
        stopped.write_text("G18 G21\nG0 X20 Z5\nG32 Z-20 F1.5\nM30\n")
        run = plan(nckit, stopped, "--machine", lathe)
        check(run.returncode == 2 and "stopped.ngc:3:1: error: G32/G33 needs the spindle turning" in run.stderr,
              "G32 with the spindle stopped is refused")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
