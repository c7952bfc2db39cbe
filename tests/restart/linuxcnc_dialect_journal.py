#!/usr/bin/env python3
"""Run journal in the LinuxCNC dialect: the persistent parameters of its .var file.

A LinuxCNC-dialect machine keeps its persistent values in the parameter file (#5161-#5390: G28,
G30, G92, the work offsets; and every parameter the file already had, such as a part counter
#1000). `nckit steps --journal` must journal their changes as it journals #500-#999 in the
Fanuc dialect, and `nckit restart --journal` must take them from the journal:

1. The header keeps them as the run found them (#1000 = 41 from the start file, #5241 = 0), and
   the records carry the changes the program makes (#1000 = 42, #5241 = 160 from its G10 L2 P2,
   #1001 = 8).
2. Cut after record k for every k, restart --journal with a live .var file that says otherwise
   (#1000 = 999) targets block k + 1, reports the journal's values (`journal.retained`), and its
   moves after the approach equal the original's from that block on (1e-9 mm).
3. The restart program run with `nckit moves --save-vars` leaves the .var file's #1000 and
   #1001 as a full run leaves them (the part is counted once).

Exit status: 0 when every check holds, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(REPO / "tests" / "macro_programs"))
from expand_roundtrip import differ  # noqa: E402

PROGRAM = REPO / "examples/restart/ngc_parts_counter.ngc"
MACHINE = REPO / "tests/real_linuxcnc/linuxcnc_mill.toml"
START = "1000\t41.000000\n1001\t7.000000\n"


class Failure(Exception):
    pass


def run(cmd: list[str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)


def moves(nckit: str, program: Path, var_file: Path, work: Path, save: bool = False) -> list[dict]:
    proc = run([nckit, "moves", str(program), "--json", "--machine", str(MACHINE), "--vars", str(var_file),
                *(["--save-vars"] if save else [])], work)
    if proc.returncode != 0:
        raise Failure(f"nckit moves {program.name}: {proc.stderr.strip()}")
    return [json.loads(t) for t in proc.stdout.splitlines() if t.strip()]


def var_values(path: Path) -> dict[int, float]:
    out = {}
    for line in path.read_text().splitlines():
        n, v = line.split()
        out[int(n)] = float(v)
    return out


def check(args, work: Path) -> str:
    start = work / "start.var"
    start.write_text(START)
    full = work / "full.var"
    full.write_text(START)
    original = moves(args.nckit, PROGRAM, full, work, save=True)
    full_values = var_values(full)
    if full_values[1000] != 42 or full_values[1001] != 8:
        raise Failure(f"a full run leaves #1000 {full_values[1000]}, #1001 {full_values[1001]}")
    run_var = work / "run.var"
    run_var.write_text(START)
    journal = work / "run.journal"
    proc = run([args.nckit, "steps", str(PROGRAM), "--machine", str(MACHINE), "--vars", str(run_var), "--journal",
                str(journal), "--journal-fsync-ms", "0", "-o", "/dev/null", "--quiet"], work)
    if proc.returncode != 0:
        raise Failure(f"nckit steps --journal: {proc.stderr.strip()}")
    lines = journal.read_bytes().split(b"\n")[:-1]
    header, records = lines[0], lines[1:]
    for wanted in (b" #1000=41 ", b" #1001=7 ", b" #5241=0 "):
        if wanted not in header:
            raise Failure(f"the header lacks {wanted.strip()!r}: {header[:200]!r}")
    for wanted in (b" #1000=42", b" #5241=160", b" #1001=8"):
        if not any(wanted in r for r in records):
            raise Failure(f"no record carries {wanted.strip()!r}")
    live = work / "live.var"
    for k in range(1, len(records)):
        cut = work / "cut.journal"
        cut.write_bytes(b"\n".join(lines[: k + 1]) + b"\n")
        live.write_text("1000\t999.000000\n1001\t999.000000\n")
        out = work / "r.ngc"
        proc = run([args.nckit, "restart", str(PROGRAM), "--journal", str(cut), "--json", "-o", str(out), "--machine",
                    str(MACHINE), "--vars", str(live)], work)
        if proc.returncode != 0:
            raise Failure(f"restart after block {k}: {proc.stderr.strip()}")
        report = json.loads(proc.stdout)
        if report["block"] != k + 1:
            raise Failure(f"restart after block {k} targets block {report['block']}")
        counter = report["journal"]["retained"].get("1000")
        if counter != 42:
            raise Failure(f"restart after block {k} reports #1000 = {counter}, the journal's is 42")
        rest = [r for r in moves(args.nckit, out, live, work, save=True) if r["line"] >= report["rest_line"]]
        expected = original[report["first_record"]:]
        if len(rest) != len(expected):
            raise Failure(f"after block {k}: {len(rest)} records after the approach, the original has {len(expected)}")
        for i, (o, r) in enumerate(zip(expected, rest)):
            if diff := differ(o, r):
                raise Failure(f"after block {k}, record {report['first_record'] + i}: {diff}")
        ended = var_values(live)
        if ended[1000] != full_values[1000] or ended[1001] != full_values[1001]:
            raise Failure(f"after block {k}: the restart leaves #1000 {ended[1000]}, #1001 {ended[1001]}; a full run "
                          f"{full_values[1000]}, {full_values[1001]}")
    return f"{len(records)} blocks journaled, restarts after blocks 1-{len(records) - 1} checked"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--nckit", required=True)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="nckit-ngc-journal-") as tmp:
        try:
            print(f"ok: {check(args, Path(tmp))}")
        except Failure as e:
            print(f"FAIL: {e}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
