#!/usr/bin/env python3
"""bench/jerk_reference.py against the closed-form time of the 7-phase S-curve on straight
moves (rest to rest, zero acceleration at both ends): the reference must land within 1e-3
relative of it. Leaving the path jerk q'·s⃛ out of the reference, or any factor in the jerk
rows wrong, moves it by several percent (without the jerk phases 100 mm at 500 mm/s² and
5,000 mm/s³ takes 1.2 s instead of 1.3 s).

Usage: jerk_reference_test.py REPO_DIR   (runs bench/jerk_reference.py on temporary programs)
"""
import json
import math
import os
import subprocess
import sys
import tempfile


def scurve_time(length, v, a, j):
    """Textbook phase durations of the symmetric rest-to-rest S-curve: jerk time tj, acceleration
    time ta (jerk phases included), cruise time tv; T = 2 ta + tv."""
    if v * j >= a * a:
        tj, ta = a / j, a / j + v / a
    else:
        tj = math.sqrt(v / j)
        ta = 2 * tj
    tv = length / v - ta
    if tv >= 0:
        return 2 * ta + tv
    if length >= 2 * a ** 3 / j ** 2:  # the acceleration limit is reached, not the speed
        tj = a / j
        ta = tj / 2 + math.sqrt(tj * tj / 4 + length / a)
    else:
        tj = (length / (2 * j)) ** (1 / 3)
        ta = 2 * tj
    return 2 * ta


CASES = [  # (G1 words, path length mm, scale of the per-axis limits along the path, jmax)
    ("X100.", 100.0, 1.0, 5000.0),            # cruise at 100 mm/s, acceleration limit reached
    ("X100.", 100.0, 1.0, 50000.0),
    ("X20.", 20.0, 1.0, 50000.0),             # no cruise, acceleration limit reached
    ("X5.", 5.0, 1.0, 5000.0),                # neither limit reached: jerk phases only
    ("X60. Y60.", 60.0 * math.sqrt(2), math.sqrt(2), 5000.0),  # both axes at their limits
]


def main():
    repo = sys.argv[1]
    script = os.path.join(repo, "bench", "jerk_reference.py")
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        for words, length, scale, jmax in CASES:
            program = os.path.join(work, "line.ngc")
            with open(program, "w") as f:
                f.write(f"G21 G17 G90 G94\nG1 {words} F100000\nM2\n")
            out = subprocess.run([sys.executable, script, program, "--jmax", str(jmax),
                                  "--start-points", "500", "--max-points", "1000"],
                                 capture_output=True, text=True, check=True).stdout
            result = json.loads(out)
            got, extrapolated = result["time_s"], result["extrapolated_s"]
            want = scurve_time(length, 100.0 * scale, 500.0 * scale, jmax * scale)
            error, error_x = abs(got - want) / want, abs(extrapolated - want) / want
            # The finest grid within 1e-3; the extrapolation of the last two grids within 2e-4.
            ok = error <= 1e-3 and error_x <= 2e-4
            failures += not ok
            print(f"{'ok  ' if ok else 'FAIL'} G1 {words} j {jmax:g}: reference {got:.6f} s "
                  f"(extrapolated {extrapolated:.6f}), closed form {want:.6f} s, "
                  f"relative error {error:.2e} ({error_x:.2e})")
    print(f"{len(CASES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
