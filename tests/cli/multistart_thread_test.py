#!/usr/bin/env python3
"""Multi-start threads from outside: G32, G92 and the one-block G76 with Q (the start angle past
the spindle index, 0.001 degree). `nckit plan --json` reports where the spindle stood when each
spindle-locked cut started; that angle, taken mod 360 in the turning sense, must be the
program's Q / 1000 for that block, for every pass, on a spindle whose speed ripples (so the
angle is no linear function of time). The starts of one thread differ in nothing but the angle:
the paths are the same. Malformed Q words are refused with FILE:LINE:COL and exit 2."""
import json
import pathlib
import re
import sys
import tempfile

from cli_checks import check, run_nckit, summary

ROOT = pathlib.Path(__file__).resolve().parents[2]


def nckit_run(nckit, *args):
    return run_nckit(nckit, *args, text=True)


# Two starts of M30 x 3 (lead 3, pitch 1.5) with G92, four passes each; a three-start thread with
# the one-block G76 (lead 6); a G32 started a quarter turn past the index.
PROGRAM = """O1234
G18 G21 G99
T0101
G97 S500 M3
G0 X34. Z5.
G92 X29.4 Z-20. F3. Q0
X28.9
X28.5
X28.16
G0 X34. Z5.
G92 X29.4 Z-20. F3. Q180000
X28.9
X28.5
X28.16
G0 X34. Z5.
G76 X27. Z-20. K1. D0.5 F6. Q0
G76 X27. Z-20. K1. D0.5 F6. Q120000
G76 X27. Z-20. K1. D0.5 F6. Q240000
G0 X30. Z5.
G32 Z-15. F2. Q90000
G0 X34.
M5
M30
"""

REVERSE = """G18 G21 G99
G97 S400 M4
G0 X34. Z5.
G92 X29. Z-20. F2. Q45000
X28.6
M30
"""


def programmed_angles(text):
    """Q / 1000 of each threading block, the G92 Q carried to the X-only passes after it."""
    angles = {}
    carried = 0.0
    for number, line in enumerate(text.splitlines(), start=1):
        q = re.search(r"Q(\d+)", line)
        if "G92" in line or "G76" in line or "G32" in line:
            carried = int(q.group(1)) / 1000.0 if q else 0.0
            angles[number] = carried
        elif re.fullmatch(r"X[\d.]+", line.strip()):
            angles[number] = carried
    return angles


def off_by_deg(spindle_deg, wanted_deg, sense):
    off = (sense * spindle_deg - wanted_deg) % 360.0
    return min(off, 360.0 - off)


def main() -> int:
    nckit = sys.argv[1]
    lathe_text = (ROOT / "examples" / "machines" / "lathe.toml").read_text()
    # A spindle whose speed swings 4 % twice a turn: the angle at a time is no straight line.
    rippled = lathe_text.replace("[spindle]\n", "[spindle]\nripple_fraction = 0.04\nripple_per_turn = 2\n"
                                 "ripple_phase_deg = 30\n", 1)
    with tempfile.TemporaryDirectory() as tmp:
        machine = pathlib.Path(tmp) / "lathe.toml"
        machine.write_text(rippled)
        program = pathlib.Path(tmp) / "multistart.nc"
        program.write_text(PROGRAM)
        run = nckit_run(nckit, "plan", "--json", "--machine", machine, program)
        check(run.returncode == 0, f"the multi-start program plans ({run.stderr.strip()})")
        sync = json.loads(run.stdout)["spindle_sync"] if run.returncode == 0 else {"first": [], "starts": 0}
        angles = programmed_angles(PROGRAM)
        by_line = {}
        for start in sync["first"]:
            by_line.setdefault(start["line"], []).append(start)
        # G92: one start per block (8); G76 K1 D0.5: depths 0.5 0.7071 0.866 1 (4 passes) x 3; G32: 1.
        check(sync["starts"] == 8 + 12 + 1, f"21 spindle-locked starts, not {sync['starts']}")
        for line, starts in sorted(by_line.items()):
            wanted = angles.get(line)
            check(wanted is not None, f"line {line} is a threading block")
            if wanted is None:
                continue
            for s in starts:
                off = off_by_deg(s["spindle_angle_deg"], wanted, 1.0)
                check(off < 1e-6, f"line {line}: the cut starts {wanted} deg past the index "
                                  f"(spindle at {s['spindle_angle_deg'] % 360.0:.6f} deg)")
                check(abs(s["start_angle_deg"] - wanted) < 1e-12, f"line {line}: start_angle_deg reported")
                # 500 rpm, slowed at most by the ripple: a wait never lasts a turn.
                check(0 <= s["wait_s"] < 60.0 / (500 * 0.96), f"line {line}: the wait is under one turn")
        check(sync["max_index_error_deg"] < 1e-6, "max_index_error_deg measures from the start angle")
        # The encoder agrees: count = floor(angle / 360 * 4096).
        for s in sync["first"]:
            check(s["encoder_count"] == int(s["spindle_angle_deg"] // (360.0 / 4096)), "encoder count at the start")

        # The two G92 starts cut the same paths; only the angle differs.
        run = nckit_run(nckit, "moves", "--json", "--machine", machine, program)
        check(run.returncode == 0, "moves --json")
        moves = [json.loads(line) for line in run.stdout.splitlines()]
        syncs = [m for m in moves if m["kind"] == "sync"]
        first, second = syncs[0:4], syncs[4:8]
        check(all(a["start"] == b["start"] and a["end"] == b["end"] for a, b in zip(first, second)),
              "both G92 starts cut the same paths")
        check(all("start_angle_deg" not in m for m in first), "Q0: no start angle in the move")
        check(all(m.get("start_angle_deg") == 180.0 for m in second), "Q180000: 180 degrees in the move")
        g76 = syncs[8:20]
        check([m.get("start_angle_deg", 0.0) for m in g76] == [0.0] * 4 + [120.0] * 4 + [240.0] * 4,
              "G76 Q: each start's passes carry its angle")

        # expand writes the angle back as Q in 0.001 degree, and the expansion reads back the same.
        run = nckit_run(nckit, "expand", "--machine", machine, program)
        check(run.returncode == 0 and " Q180000" in run.stdout and " Q120000" in run.stdout,
              "expand keeps the start angle")
        expanded = pathlib.Path(tmp) / "expanded.ngc"
        expanded.write_text(run.stdout)
        again = nckit_run(nckit, "moves", "--json", "--machine", machine, expanded)
        again_syncs = [json.loads(line) for line in again.stdout.splitlines() if '"sync"' in line]
        check([m.get("start_angle_deg") for m in again_syncs] == [m.get("start_angle_deg") for m in syncs],
              "the expansion reads back with the same start angles")

        # M4: the angle is past the index in the turning sense, so the spindle stands at -Q.
        reverse = pathlib.Path(tmp) / "reverse.nc"
        reverse.write_text(REVERSE)
        run = nckit_run(nckit, "plan", "--json", "--machine", machine, reverse)
        check(run.returncode == 0, f"the M4 program plans ({run.stderr.strip()})")
        if run.returncode == 0:
            starts = json.loads(run.stdout)["spindle_sync"]["first"]
            check(len(starts) == 2, "two M4 passes")
            for s in starts:
                check(off_by_deg(s["spindle_angle_deg"], 45.0, -1.0) < 1e-6,
                      f"M4: 45 deg past the index backwards (spindle at {s['spindle_angle_deg']:.6f})")

        # Malformed: each refused with FILE:LINE:COL, exit 2; check and plan print nothing on stdout.
        bad_cases = {
            "G92 X29. Z-20. F2. Q180.": "decimal point",
            "G92 X29. Z-20. F2. Q360001": "0 to 360000",
            "G92 X29. Z-20. F2. Q-1000": "0 to 360000",
            "G32 Z-20. F2. Q1.5": "decimal point",
            "G90 X29. Z-20. F0.2 Q1000": "takes no Q",
            "G76 X27. Z-20. K1. D0.5 F6. P2": "only infeed P1",
        }
        for block, message in bad_cases.items():
            bad = pathlib.Path(tmp) / "bad.nc"
            bad.write_text(f"G18 G21 G99\nG97 S500 M3\nG0 X34. Z5.\n{block}\nM30\n")
            run = nckit_run(nckit, "check", "--machine", machine, bad)
            column = block.index(next(w for w in ("Q", "P2") if w in block)) + 1
            check(run.returncode == 2 and f"bad.nc:4:{column}: error:" in run.stderr and message in run.stderr
                  and run.stdout == "", f"'{block}' refused at 4:{column} ({run.stderr.strip()})")
            run = nckit_run(nckit, "plan", "--machine", machine, bad)
            check(run.returncode == 2 and run.stdout == "", f"'{block}': plan moves nothing")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
