#!/usr/bin/env python3
"""Operator messages in real LinuxCNC: `rs274 -p <plug-in> -g programs/operator_messages.nc`
must load the plug-in and print LinuxCNC's MESSAGE canonical call for each `(MSG, ...)` comment
and for `#3006 = 1 (...)`, in program order between the moves around them, with the #3006
stop (PROGRAM_STOP) right after its message.

  messages.py --plugin LIB.so --program operator_messages.nc
  messages.py --plugin LIB.so --program ngc_messages.ngc --machine LINUXCNC_DIALECT.toml

With --machine (a machine file in LinuxCNC's dialect, given to the plug-in through an INI's
[NCKIT] MACHINE), the program is LinuxCNC G-code: the MESSAGE calls and the motions among them,
in order, must be those LinuxCNC's own interpreter prints for the same program (`rs274 -g`
without -p), and there must be at least one message.

Exit status 0 when the calls come so, 1 otherwise.
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rs274_support import calls, find_rs274, plugin_loaded, run_rs274  # noqa: E402

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


def against_builtin(rs274, args):
    """The plug-in (LinuxCNC dialect) against LinuxCNC's own interpreter: same messages, same order."""
    wanted = ("MESSAGE(", "STRAIGHT_", "ARC_FEED(")
    with tempfile.TemporaryDirectory(prefix="nckit-plugin-msg-") as work:
        ini = os.path.join(work, "plugin.ini")
        with open(ini, "w") as f:
            f.write(f"[NCKIT]\nMACHINE = {os.path.abspath(args.machine)}\n")
        ours = run_rs274(rs274, args.program, plugin=args.plugin, ini=ini, cwd=work)
        theirs = run_rs274(rs274, args.program, cwd=work)
    if (why := plugin_loaded(ours, args.plugin)):
        print(f"FAIL {why}")
        return 1
    for name, proc in (("the plug-in", ours), ("LinuxCNC's interpreter", theirs)):
        if proc.returncode != 0:
            print(f"FAIL {name}: rs274 exit status {proc.returncode}: {proc.stderr.strip()[:300]}")
            return 1
    got, expected = calls(ours.stdout, wanted), calls(theirs.stdout, wanted)
    messages = [c for c in expected if c.startswith("MESSAGE(")]
    if not messages:
        print("FAIL LinuxCNC's own interpreter printed no MESSAGE: nothing to compare")
        return 1
    if got != expected:
        for i, (a, b) in enumerate(zip(got + [""] * len(expected), expected + [""] * len(got))):
            if a != b:
                print(f"FAIL call {i + 1}: the plug-in printed {a!r}, LinuxCNC's interpreter {b!r}")
                break
        return 1
    print(f"{len(messages)} messages among {len(expected)} calls as LinuxCNC's interpreter prints them")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--program", required=True)
    ap.add_argument("--machine", help="machine file in LinuxCNC's dialect: compare with rs274's own")
    ap.add_argument("--rs274")
    args = ap.parse_args()
    rs274 = find_rs274(args.rs274)
    if not rs274:
        print("error: LinuxCNC's rs274 not found; run scripts/deps.sh", file=sys.stderr)
        return 1
    if args.machine:
        return against_builtin(rs274, args)
    proc = run_rs274(rs274, args.program, plugin=args.plugin)
    if (why := plugin_loaded(proc, args.plugin)):
        print(f"FAIL {why}")
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
