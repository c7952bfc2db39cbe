#!/usr/bin/env python3
"""Runs one numbered API example and checks what it prints: against the nckit command on the
same program (the program is read from the example's source), or against the maths.
Usage: check_examples.py NAME EXAMPLE_BINARY NCKIT EXAMPLES_DIR"""
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path


def program_text(source: Path, name: str) -> str:
    """The raw string literal `name = R"nc(...)nc"` of an example's source."""
    match = re.search(name + r'\s*=\s*R"nc\((.*?)\)nc"', source.read_text(encoding="utf-8"), re.S)
    if not match:
        raise SystemExit(f"{source}: no program '{name}'")
    return match.group(1)


def run(command, cwd=None, status=0):
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True, cwd=cwd, timeout=120)
    if done.returncode != status:
        raise SystemExit(f"{command}: exit {done.returncode} (want {status})\n{done.stdout}{done.stderr}")
    return done


def check(condition, message):
    if not condition:
        raise SystemExit(f"FAIL: {message}")


def check_interpret(example, nckit, source, work: Path):
    """01 prints exactly what `nckit moves` prints, then the bad program's moves and the
    diagnostic nckit prints for it."""
    (work / "outline.nc").write_text(program_text(source, "program"))
    (work / "bad.nc").write_text(program_text(source, "bad_program"))
    good = run([nckit, "moves", "outline.nc"], cwd=work).stdout
    bad = run([nckit, "moves", "bad.nc"], cwd=work, status=2)
    expected = good + "--\n" + bad.stdout + bad.stderr.splitlines()[0] + "\n"
    got = run([example], cwd=work).stdout
    check(got == expected, f"01 prints\n{got}\nnckit moves prints\n{expected}")
    check(re.search(r"^bad\.nc:3:\d+: error: ", got, re.M), "01: the bad arc is reported at bad.nc:3")
    check(got.count("\nG3 ") == 1 and len(good.splitlines()) >= 9, "01: the outline's moves")


def check_plan(example, nckit, source, work: Path):
    """02's cycle time is `nckit plan`'s; its samples are consistent (finite differences of the
    positions give the velocities), within the machine's speed, and near the programmed arc."""
    (work / "outline.nc").write_text(program_text(source, "program"))
    plan = run([nckit, "plan", "outline.nc"], cwd=work).stdout
    lines = run([example], cwd=work).stdout.splitlines()
    cycle = re.search(r"^cycle time: ([0-9.]+) s$", plan, re.M).group(1)
    check(lines[0] == f"cycle time: {cycle} s", f"02: '{lines[0]}', nckit plan: cycle time {cycle} s")
    check(lines[2] == "t_s,x_mm,y_mm,z_mm,vx_mm_s,vy_mm_s,vz_mm_s", "02: the sample header")
    rows = [[float(v) for v in line.split(",")] for line in lines[3:]]
    period, duration = 0.002, float(cycle)
    check(len(rows) == math.floor(duration / period + 1e-9) + 1, f"02: {len(rows)} samples over {duration} s")
    # Central differences: error at most jerk × period² / 6 (50000 mm/s³ on the built-in mill),
    # plus the printed rounding.
    tolerance = 50000 * period**2 / 6 + 2e-6 / period
    for before, row, after in zip(rows, rows[1:], rows[2:]):
        for axis in range(3):
            difference = (after[1 + axis] - before[1 + axis]) / (2 * period)
            check(abs(difference - row[4 + axis]) <= tolerance,
                  f"02: t={row[0]} axis {axis}: difference {difference} vs velocity {row[4 + axis]}")
            check(abs(row[4 + axis]) <= 100 + 1e-6, f"02: t={row[0]} faster than 100 mm/s")
    # G64 without P: the path may leave the programmed one by 0.05 mm where the planner joins
    # the line and the arc smoothly, and by no more.
    on_arc = [r for r in rows if r[1] > 10 and r[2] < 5 and abs(r[3] + 1) < 1e-9]
    check(len(on_arc) > 100, f"02: {len(on_arc)} samples on the arc")
    for r in on_arc:
        check(abs(math.hypot(r[1] - 10, r[2] - 5) - 5) <= 0.05, f"02: t={r[0]} off the R5 arc: {r}")
    check(max(abs(rows[-1][1]), abs(rows[-1][2]), abs(rows[-1][3] - 5)) < 1e-3, f"02: ends at {rows[-1]}")


def check_steps(example, nckit, source, work: Path):
    """03's first events and per-axis tallies are those of `nckit steps --text`; the counts follow
    from the geometry at 800 steps/mm (X out 4 mm and back, Y up 2 mm over the arc and back)."""
    (work / "steps.nc").write_text(program_text(source, "program"))
    events = [line.split() for line in run([nckit, "steps", "--text", "steps.nc"], cwd=work).stdout.splitlines()]
    lines = run([example], cwd=work).stdout.splitlines()
    check(lines[:5] == [" ".join(e) for e in events[:5]], f"03: first events {lines[:5]} vs {events[:5]}")
    for axis, letter in enumerate("XYZ"):
        mine = [e for e in events if int(e[1]) == axis]
        forward = sum(1 for e in mine if e[2] == "1")
        backward = sum(1 for e in mine if e[2] == "-1")
        last = int(mine[-1][0]) if mine else -1
        expected = f"{letter}: +{forward} -{backward} count {forward - backward} last_ns {last}"
        check(lines[5 + axis] == expected, f"03: '{lines[5 + axis]}', nckit steps: '{expected}'")
        check((forward, backward) == {"X": (3200, 3200), "Y": (1600, 1600), "Z": (0, 0)}[letter],
              f"03: {letter} made {forward} steps forward and {backward} back")


def check_cam(example, nckit, source, work: Path):
    """04's table meets 1 nm and its values are the formula's (θ wraps, Z clamps to 0..20)."""
    lines = run([example], cwd=work).stdout.splitlines()
    check(re.fullmatch(r"formula error at byte \d+: .+", lines[0]), f"04: '{lines[0]}'")
    cells = re.fullmatch(r"cells: (\d+) x (\d+), (\d+) bytes, error bound (\S+) mm, tolerance met: yes", lines[1])
    check(cells and float(cells.group(4)) <= 1e-6, f"04: '{lines[1]}'")
    check(lines[2] == "theta_deg,z_mm,r_mm" and len(lines) == 3 + 7 * 4, "04: the value table")
    for line in lines[3:]:
        theta, z, r = (float(v) for v in line.split(","))
        exact = 0.1 * math.cos(math.radians(2 * theta)) + 0.002 * min(max(z, 0), 20)
        check(abs(r - exact) <= 1e-6 + 1e-9, f"04: r({theta}, {z}) = {r}, the formula gives {exact}")


CHECKS = {"01_interpret": check_interpret, "02_plan": check_plan, "03_steps": check_steps, "04_cam": check_cam}


def main() -> int:
    name, example, nckit, directory = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3]), Path(sys.argv[4])
    with tempfile.TemporaryDirectory() as tmp:
        CHECKS[name](example.resolve(), nckit.resolve(), directory / f"{name}.cpp", Path(tmp))
    print(f"{name}: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
