#!/usr/bin/env python3
"""Operator messages in real LinuxCNC: `rs274 -p <plug-in> -g programs/operator_messages.nc`
must load the plug-in and print LinuxCNC's MESSAGE canonical call for each `(MSG, ...)` comment
and for `#3006 = 1 (...)`, in program order between the moves around them, with the #3006
stop (PROGRAM_STOP) right after its message.

  messages.py --plugin LIB.so --program operator_messages.nc

Exit status 0 when the calls come so, 1 otherwise.
"""
import argparse
import os
import shutil
import subprocess
import sys

# What must appear, in this order, among rs274's calls (each a substring of one line).
EXPECTED = [
    "STRAIGHT_TRAVERSE(",            # G0 X0 Y0 Z5
    'MESSAGE("Check the clamps")',
    "STRAIGHT_FEED(10.0000",         # G1 X10
    'MESSAGE("second message ")',
    "STRAIGHT_FEED(10.0000, 10.0000",  # G1 Y10
    'MESSAGE("TURN THE PART OVER")',
    "PROGRAM_STOP()",
    "STRAIGHT_FEED(0.0000, 10.0000",   # G1 X0
    "PROGRAM_END()",
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--program", required=True)
    ap.add_argument("--rs274", default=shutil.which("rs274"))
    args = ap.parse_args()
    if not args.rs274:
        print("error: LinuxCNC's rs274 not found; run scripts/deps.sh", file=sys.stderr)
        return 1
    plugin = os.path.abspath(args.plugin)
    proc = subprocess.run([args.rs274, "-p", plugin, "-g", os.path.abspath(args.program)],
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    if f"using custom interpreter '{plugin}'" not in proc.stderr:
        print(f"FAIL rs274 did not load the plug-in: {proc.stderr.strip()[:300]}")
        return 1
    if proc.returncode != 0:
        print(f"FAIL rs274 exit status {proc.returncode}: {proc.stderr.strip()[:300]}")
        return 1
    lines = proc.stdout.splitlines()
    at = 0
    for want in EXPECTED:
        while at < len(lines) and want not in lines[at]:
            if "MESSAGE(" in lines[at] or "STRAIGHT_" in lines[at]:
                print(f"FAIL expected {want!r} next, got: {lines[at].strip()}")
                return 1
            at += 1
        if at == len(lines):
            print(f"FAIL {want!r} not found in order; rs274 printed:\n{proc.stdout}")
            return 1
        at += 1
    print(f"all {len(EXPECTED)} calls in order")
    return 0


if __name__ == "__main__":
    sys.exit(main())
