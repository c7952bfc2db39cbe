#!/usr/bin/env python3
"""Bad plug-in settings in real LinuxCNC: `rs274 -p <plug-in> -i BAD.ini -g PROGRAM` must load the
plug-in, report the setting at fault as `FILE:LINE:COL: error: ...` and issue no motion.

  ini_errors.py --plugin LIB.so --program PROGRAM.ngc

Cases: a tool table that does not exist ([EMCIO] TOOL_TABLE, LinuxCNC's own key), a tool table
with a bad row ([NCKIT] TOOL_TABLE), EXACT_PATH with a value other than 0 or 1, an unknown
[NCKIT] key, a JOURNAL_FSYNC_MS that is no number, a JOURNAL in a folder that does not exist.
Exit status 0 when every case is reported so, 1 otherwise.
"""
import argparse
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rs274_support import find_rs274, plugin_loaded, run_rs274  # noqa: E402

CASES = [
    # (name, INI text, tool table text or None, what stderr must say)
    ("missing tool table", "[EMCIO]\nTOOL_TABLE = nothere.tbl\n", None,
     r"nothere\.tbl:0:0: error: cannot read tool file"),
    ("bad tool table row", "[NCKIT]\nTOOL_TABLE = tools.tbl\n", "T1 P1 Z10.0 D6.0\nT2 P2 Zabc\n",
     r"tools\.tbl:2:\d+: error: "),
    ("bad EXACT_PATH", "[NCKIT]\nEXACT_PATH = yes\n", None,
     r"plugin\.ini:2:1: error: \[NCKIT\] EXACT_PATH = yes: expected 0 or 1"),
    ("unknown key", "[NCKIT]\nTOOLTABLE = tools.tbl\n", None,
     r"plugin\.ini:2:1: error: \[NCKIT\] unknown key TOOLTABLE"),
    ("bad JOURNAL_FSYNC_MS", "[NCKIT]\nJOURNAL = run.journal\nJOURNAL_FSYNC_MS = soon\n", None,
     r"plugin\.ini:3:1: error: \[NCKIT\] JOURNAL_FSYNC_MS = soon: expected a whole number of ms"),
    ("journal in a missing folder", "[NCKIT]\nJOURNAL = no/such/folder/run.journal\n", None,
     r"run\.journal:1:1: error: run journal: cannot create"),
]


def run_case(args, name, ini_text, table_text, wanted):
    with tempfile.TemporaryDirectory(prefix="nckit-plugin-ini-") as work:
        ini = os.path.join(work, "plugin.ini")
        with open(ini, "w") as f:
            f.write(ini_text)
        if table_text is not None:
            with open(os.path.join(work, "tools.tbl"), "w") as f:
                f.write(table_text)
        proc = run_rs274(args.rs274, args.program, plugin=args.plugin, ini=ini, cwd=work)
    if (why := plugin_loaded(proc, args.plugin)):
        return f"{name}: {why}"
    if not re.search(wanted, proc.stderr):
        return f"{name}: expected /{wanted}/ on stderr, got: {proc.stderr.strip()[:300]}"
    if proc.returncode == 0:
        return f"{name}: rs274 exited 0"
    if "STRAIGHT_" in proc.stdout or "ARC_FEED" in proc.stdout:
        return f"{name}: motion was issued: {proc.stdout.strip()[:200]}"
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--program", required=True)
    ap.add_argument("--rs274")
    args = ap.parse_args()
    args.rs274 = find_rs274(args.rs274)
    if not args.rs274:
        print("error: LinuxCNC's rs274 not found; run scripts/deps.sh", file=sys.stderr)
        return 1
    args.plugin = os.path.abspath(args.plugin)
    args.program = os.path.abspath(args.program)
    failures = [f for f in (run_case(args, *case) for case in CASES) if f]
    for f in failures:
        print(f"FAIL {f}")
    print(f"{len(CASES) - len(failures)} of {len(CASES)} bad settings reported")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
