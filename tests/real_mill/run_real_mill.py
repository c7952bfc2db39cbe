#!/usr/bin/env python3
"""Real mill programs through `nckit check`, `nckit moves` and LinuxCNC's `rs274 -g`.

Every program listed in programs.csv (CAM-post output in cam/, hand-written shop programs in
shop/) is run three ways with the machine file the list names (mill.toml: numbers without a
decimal point are whole units; haas.toml: they count least increments, as on a Haas or Fanuc
control) and a copy of the tool table tools.tbl with the cutter sizes the program's own text
states (program_tools.py, README.md "Tool data"):

- `nckit check` — accepted when it exits 0;
- `rs274 -g` with that table scaled by 1/25.4 (standalone rs274 reads tool tables as
  inches) — accepted when it exits 0;
- where both accept, `nckit moves --json` is compared with rs274's motions by
  tests/programs/compare_linuxcnc.py (kind, end point, arc centre and direction, feed, source
  line; 1e-4 mm, i.e. equal to 4 decimals).

Each result is checked against the list's expectations (nckit, rs274, compare columns), so an
interpreter change that refuses a program nckit used to run, or that moves differently from
LinuxCNC, fails the run. A program the list marks `differs` names the dialect difference in its
note column. Finally a table of acceptance by category is printed (the figures in
BENCHMARKS.md).

Usage: run_real_mill.py [--nckit BIN] [--rs274 BIN] [--markdown] [--show-tools] [NAME ...]
Exit status: 0 when every program behaves as the list says, 1 otherwise.
"""

from __future__ import annotations

import argparse
import csv
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "programs"))
import compare_linuxcnc as cl  # noqa: E402
import program_tools  # noqa: E402

# compare_linuxcnc's own sanity check of rs274's arcs (start and end radius equal to 1e-4) holds
# for the programs written for it; real CAM output rounded to 3-4 decimals runs within LinuxCNC's
# tolerance instead (cam/28 ends an 895 mm arc 0.025 mm off): compare what both run.
cl.check_reference = lambda motions, machine: None
_drop_zero_length = cl.drop_zero_length


def drop_zero_length_from_home(motions, tol=1e-6):
    """compare_linuxcnc's drop_zero_length, with the machine's start (home, all axes 0 on both
    sides) as the position before the first motion, so a first traverse to where the machine
    already stands goes as well. An arc of radius 0 that ends where it starts goes too: rs274
    writes one where the tool pivots inside an arc of its own radius (nckit writes a straight move
    that goes nowhere)."""
    home = cl.Motion(kind="rapid", end={a: 0.0 for a in cl.ALL_AXES})
    kept, prev = [], None
    for mo in _drop_zero_length([home, *motions], tol)[1:]:
        pivot = (mo.kind == "arc" and prev is not None and mo.center
                 and all(abs(mo.end[a] - prev[a]) <= tol for a in mo.end if a in prev)
                 and all(abs(mo.center[a] - mo.end[a]) <= tol for a in mo.center if a in mo.end))
        if not pivot:
            kept.append(mo)
            prev = mo.end
    return kept


cl.drop_zero_length = drop_zero_length_from_home

TIMEOUT_S = 120.0


@dataclass
class Entry:
    path: Path
    category: str   # cam or shop
    system: str     # the CAM system or control the program was written for
    machine: Path
    nckit: str      # accept / refuse
    rs274: str      # accept / refuse
    compare: str    # equal / differs / - (not both accept)
    note: str


@dataclass
class Outcome:
    nckit: str
    rs274: str
    compare: str
    detail: str


def read_list(path: Path) -> list[Entry]:
    entries = []
    with open(path, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            entries.append(Entry(HERE / row["file"], row["category"], row["system"],
                                 HERE / row["machine"], row["nckit"], row["rs274"],
                                 row["compare"], row["note"]))
    return entries


def library_options() -> list[str]:
    """Programs called by M98/G65 from another file (shop/library/O1002.nc ...), as a control
    holds them in its memory beside the main program."""
    library = HERE / "shop" / "library"
    return ["--library", str(library)] if library.is_dir() else []


def nckit_check(nckit: str, entry: Entry, tools: Path) -> tuple[bool, str]:
    proc = subprocess.run([nckit, "check", str(entry.path), "--machine", str(entry.machine),
                           "--tools", str(tools), *library_options()],
                          capture_output=True, text=True, timeout=TIMEOUT_S,
                          stdin=subprocess.DEVNULL)
    first = next((l for l in proc.stderr.splitlines() if ": error:" in l), "")
    if proc.returncode not in (0, 2):
        return False, f"nckit check exit status {proc.returncode} (a crash?): {proc.stderr[:200]}"
    return proc.returncode == 0, first


def program_tool_table(entry: Entry, workdir: Path, show: bool) -> Path:
    """tools.tbl with the cutter sizes the program's own text states (program_tools.py)."""
    data = program_tools.derive(entry.path, entry.system == "Fusion 360")
    if show:
        for number, reason in sorted(data.reasons.items()):
            print(f"     {entry.category}/{entry.path.name}: D{number} = "
                  f"{data.diameters_mm[number]:.4f} mm diameter ({reason})")
    return program_tools.write_table(HERE / "tools.tbl", data, workdir / "program_tools.tbl")


def run_one(entry: Entry, args, workdir: Path) -> Outcome:
    tools = program_tool_table(entry, workdir, args.show_tools)
    accepted, first_error = nckit_check(args.nckit, entry, tools)
    setup = cl.Setup(machine_file=entry.machine, tools_file=tools)
    try:
        ref = cl.reference(entry.path, args.rs274, HERE, workdir, TIMEOUT_S, setup=setup)
    except cl.ProgramError as e:
        text = str(e)
        # check_reference() refuses rs274 motions beyond the travel: rs274 itself ran.
        rs274 = "accept" if "rs274 exit status" not in text else "refuse"
        return Outcome("accept" if accepted else "refuse", rs274, "-",
                       first_error or f"rs274: {text[:160]}")
    if not accepted:
        return Outcome("refuse", "accept", "-", first_error)
    src = entry.path.read_text(encoding="utf-8", errors="replace").splitlines()
    # rs274 writes a zero-length traverse for a G0 block without axis words (`G0 G90 G40 ...`,
    # `N2 G0 G17 G40 G49 G80 G90`): it moves nothing, and nckit writes none.
    args.skip_zero_length = True
    args.timeout = TIMEOUT_S
    ok, message = cl.compare_program(entry.path, ref, entry.path, src, args, workdir, True,
                                     library_options())
    return Outcome("accept", "accept", "equal" if ok else "differs",
                   "" if ok else message.split(": ", 1)[-1].splitlines()[0][:200])


def table(entries: list[Entry], outcomes: list[Outcome], markdown: bool) -> str:
    rows = []
    for category in ("cam", "shop"):
        chosen = [(e, o) for e, o in zip(entries, outcomes) if e.category == category]
        if not chosen:
            continue
        n = len(chosen)
        nk = sum(o.nckit == "accept" for _, o in chosen)
        rs = sum(o.rs274 == "accept" for _, o in chosen)
        both = sum(o.nckit == "accept" and o.rs274 == "accept" for _, o in chosen)
        equal = sum(o.compare == "equal" for _, o in chosen)
        rows.append((category, n, nk, rs, both, equal))
    out = []
    if markdown:
        out.append("| category | programs | nckit accepts | rs274 accepts | both | equal moves |")
        out.append("|---|---:|---:|---:|---:|---:|")
        for c, n, nk, rs, both, eq in rows:
            out.append(f"| {c} | {n} | {nk} ({100 * nk / n:.0f} %) | {rs} ({100 * rs / n:.0f} %) "
                       f"| {both} | {eq} of {both} |")
    else:
        for c, n, nk, rs, both, eq in rows:
            out.append(f"{c:5s} {n:3d} programs: nckit accepts {nk} ({100 * nk / n:.0f} %), "
                       f"rs274 {rs} ({100 * rs / n:.0f} %); both {both}, equal moves {eq}")
    return "\n".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="programs to run (part of the file name)")
    ap.add_argument("--nckit", default=str(cl.DEFAULT_NCKIT))
    ap.add_argument("--rs274", default=None)
    ap.add_argument("--markdown", action="store_true", help="print the summary as a table")
    ap.add_argument("--show-tools", action="store_true",
                    help="print the D offsets each program's own tool data set, and why")
    args = ap.parse_args()
    args.nckit = str(Path(args.nckit).resolve())
    args.rs274 = args.rs274 or shutil.which("rs274")
    if not args.rs274:
        print("run_real_mill: rs274 not on PATH: run scripts/deps.sh (linuxcnc-uspace)")
        return 1
    args.feed = True
    entries = read_list(HERE / "programs.csv")
    if args.names:
        entries = [e for e in entries if any(n in e.path.name for n in args.names)]
    outcomes, failures = [], 0
    with tempfile.TemporaryDirectory(prefix="nckit-real-mill-") as tmp:
        for entry in entries:
            workdir = Path(tmp) / entry.path.stem
            workdir.mkdir()
            got = run_one(entry, args, workdir)
            outcomes.append(got)
            expected = (entry.nckit, entry.rs274, entry.compare)
            actual = (got.nckit, got.rs274, got.compare)
            status = "ok  " if expected == actual else "FAIL"
            failures += expected != actual
            name = f"{entry.category}/{entry.path.name}"
            print(f"{status} {name}: nckit {got.nckit}, rs274 {got.rs274}, moves {got.compare}"
                  + (f" (expected {'/'.join(expected)})" if expected != actual else "")
                  + (f"\n       {got.detail}" if got.detail else ""))
    print(table(entries, outcomes, args.markdown))
    print(f"run_real_mill: {len(entries) - failures} of {len(entries)} programs as listed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
