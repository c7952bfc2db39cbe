#!/usr/bin/env python3
"""Real LinuxCNC programs: `nckit moves --dialect linuxcnc` against LinuxCNC's `rs274 -g`.

Every `programs/*.ngc` runs in both. A program rs274 accepts must give nckit's moves equal to
rs274's (kind, end points, arc centres and directions to rs274's 4 decimals, feeds; the rules
of tests/programs/compare_linuxcnc.py, whose reading of rs274's output this reuses). A program
rs274 rejects must be rejected by nckit too, with `FILE:LINE:COL: error:` and exit status 2.
Subroutine files (`library/NAME.ngc`) are found by both: nckit through `--library`, rs274 in its
working folder, where they are copied.

`--summary` prints the acceptance figures for BENCHMARKS.md instead of failing on the first
difference: programs, accepted by rs274, accepted by nckit, equal moves.
Exit status: 0 when every program agrees, 1 otherwise.
"""

from __future__ import annotations

import argparse
import fcntl
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "programs"))
import compare_linuxcnc as cl  # noqa: E402

MACHINE = HERE / "linuxcnc_mill.toml"  # dialect = "linuxcnc", wide travel, X Y Z A B C
ERROR_RE = re.compile(r"^.+:\d+:\d+: error: ", re.MULTILINE)


def nckit_verdict(nckit: str, program: Path, library: Path, workdir: Path, timeout: float):
    """(exit status, stderr) of `nckit moves --dialect linuxcnc` on the program."""
    cmd = [nckit, "moves", str(program), "--json", "--machine", str(MACHINE), "--library", str(library)]
    proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=timeout)
    return proc.returncode, proc.stderr


def check(program: Path, args, workdir: Path) -> tuple[str, str]:
    """('match' | 'both-reject' | 'fail', message) for one program."""
    for sub in args.library.glob("*.ngc"):
        shutil.copy(sub, workdir / sub.name)
    try:
        ref = cl.reference(program, args.rs274, args.machines, workdir, args.timeout,
                           setup=cl.Setup(machine_file=args.machine))
    except cl.ProgramError as e:
        status, stderr = nckit_verdict(args.nckit, program, args.library, workdir, args.timeout)
        if status == 2 and ERROR_RE.search(stderr):
            first = ERROR_RE.search(stderr)
            line = stderr[first.start():].splitlines()[0]
            return "both-reject", f"ok {program.stem}: both reject it (rs274: {e}; nckit: {line})"
        return "rs274-rejects", (f"FAIL {program.stem}: rs274 rejects it ({e}) but nckit exits {status}"
                                 f"{': ' + stderr.strip().splitlines()[0] if stderr.strip() else ''}")
    src = program.read_text(encoding="utf-8", errors="replace").splitlines()
    extra = ["--library", str(args.library)]
    ok, message = cl.compare_program(program, ref, program, src, args, workdir, not args.ignore_lines,
                                     extra)
    if ok:
        return "match", message
    status, _ = nckit_verdict(args.nckit, program, args.library, workdir, args.timeout)
    return ("differs" if status == 0 else "nckit-rejects"), message


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="programs to run (file name or stem)")
    ap.add_argument("--nckit", default=str(cl.DEFAULT_NCKIT))
    ap.add_argument("--rs274", default=None)
    ap.add_argument("--programs", type=Path, default=HERE / "programs")
    ap.add_argument("--library", type=Path, default=HERE / "library")
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--ignore-lines", action="store_true", help="do not compare source lines")
    ap.add_argument("--summary", action="store_true", help="print acceptance figures")
    ap.add_argument("--lock", type=Path, default=None,
                    help="hold an flock on this file for the run (CTest: /tmp/nckit-linuxcnc.lock, "
                         "which manual runs take with `flock`): one LinuxCNC at a time on the machine")
    args = ap.parse_args()
    if args.lock is not None:
        lock_file = open(args.lock, "a")  # noqa: SIM115 - held until the process exits
        fcntl.flock(lock_file, fcntl.LOCK_EX)
    args.rs274 = args.rs274 or shutil.which("rs274")
    if not args.rs274:
        print("error: LinuxCNC's rs274 not found; run scripts/deps.sh", file=sys.stderr)
        return 1
    args.nckit = str(Path(args.nckit).resolve())
    if not os.access(args.nckit, os.X_OK):
        print(f"error: nckit binary {args.nckit} not found; build it first", file=sys.stderr)
        return 1
    args.programs, args.library = args.programs.resolve(), args.library.resolve()
    args.machines = cl.DEFAULT_MACHINES
    args.machine = MACHINE
    args.feed, args.skip_zero_length = True, False
    programs = cl.select_programs(args.programs, args.names)
    counts: dict[str, int] = {}
    with tempfile.TemporaryDirectory(prefix="nckit-real-linuxcnc-") as tmp:
        for program in programs:
            workdir = Path(tempfile.mkdtemp(dir=tmp))
            try:
                verdict, message = check(program, args, workdir)
            except subprocess.TimeoutExpired:
                verdict, message = "fail", f"FAIL {program.stem}: timed out"
            counts[verdict] = counts.get(verdict, 0) + 1
            print(message, flush=True)
    total = len(programs)
    rs274_accepts = total - counts.get("both-reject", 0) - counts.get("rs274-rejects", 0)
    nckit_accepts = counts.get("match", 0) + counts.get("differs", 0) + counts.get("rs274-rejects", 0)
    print(f"{total} programs: rs274 accepts {rs274_accepts}, nckit accepts {nckit_accepts}, "
          f"equal moves {counts.get('match', 0)}, both reject {counts.get('both-reject', 0)}, "
          f"nckit rejects what rs274 runs {counts.get('nckit-rejects', 0)}, moves differ "
          f"{counts.get('differs', 0)}, nckit runs what rs274 rejects {counts.get('rs274-rejects', 0)}")
    if args.summary:
        return 0
    return 0 if counts.get("match", 0) + counts.get("both-reject", 0) == total else 1


if __name__ == "__main__":
    sys.exit(main())
