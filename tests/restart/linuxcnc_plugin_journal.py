#!/usr/bin/env python3
"""The LinuxCNC plug-in's run journal ([NCKIT] JOURNAL) read back by `nckit restart --journal`.

For each program it writes an INI whose [NCKIT] section names the machine file, a RETAINED file
holding #500-#502 and a JOURNAL with JOURNAL_FSYNC_MS = 0, and runs the program through the
plug-in in LinuxCNC's own standalone interpreter (`rs274 -p PLUGIN -i INI -g PROGRAM`). Then:

1. The journal holds a header and one record per block that nckit counts for the program
   (`nckit restart --block` beyond the end names that count), every record's CRC-32 (zlib's)
   holds, the header keeps #500-#502 as the run found them, and a block that changed #500 says
   so.
2. Cut after record k (the journal a run interrupted after block k leaves: records are appended
   in order and never rewritten) for a few k, `nckit restart --journal CUT PROGRAM` must target
   block k + 1, arrive at the journal's position and retained values (restart checks both), and
   its moves after the approach must equal the original run's from that block on (1e-9 mm, the
   comparison of restart_every_block.py). The whole journal must be refused as
   `restart-run-complete` ("nothing is left to restart").

Exit status: 0 when every check holds, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(REPO / "tests" / "macro_programs"))
sys.path.insert(0, str(REPO / "tests" / "linuxcnc_plugin"))
from expand_roundtrip import differ  # noqa: E402
from per_program import Failure, run_each  # noqa: E402
from rs274_support import plugin_loaded  # noqa: E402

MACHINE = "examples/machines/mill.toml"
PROGRAMS = ["examples/restart/parts_counter.nc", "examples/restart/rotated_slots.nc"]
RETAINED_START = "#500 = 41\n#501 = 0\n#502 = 40\n"


def run(cmd: list[str], cwd: Path, timeout: int = 120) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=timeout)


def records_of(journal: bytes) -> list[bytes]:
    """The journal's lines, each checked against its CRC-32."""
    lines = journal.split(b"\n")
    if lines[-1] != b"":
        raise Failure("the journal does not end with a complete record")
    out = []
    for line in lines[:-1]:
        payload, _, crc = line.rpartition(b" *")
        if int(crc, 16) != zlib.crc32(payload):
            raise Failure(f"a record's checksum does not hold: {line[:80]!r}")
        out.append(payload)
    return out


def moves(nckit: str, program: Path, vars_file: Path, work: Path) -> list[dict]:
    proc = run([nckit, "moves", str(program), "--json", "--machine", str(REPO / MACHINE), "--vars", str(vars_file)],
               work)
    if proc.returncode != 0:
        raise Failure(f"nckit moves {program.name}: {proc.stderr.strip()}")
    return [json.loads(t) for t in proc.stdout.splitlines() if t.strip()]


def check_program(args, name: str, work: Path) -> str:
    program = REPO / name
    start_vars = work / "start.vars"
    start_vars.write_text(RETAINED_START)
    plugin_vars = work / "plugin.vars"
    plugin_vars.write_text(RETAINED_START)
    journal = work / "run.journal"
    ini = work / "plugin.ini"
    ini.write_text(f"[NCKIT]\nMACHINE = {REPO / MACHINE}\nRETAINED = {plugin_vars}\nJOURNAL = {journal}\n"
                   "JOURNAL_FSYNC_MS = 0\n")
    proc = run([args.rs274, "-p", os.path.abspath(args.plugin), "-i", str(ini), "-g", str(program)], work)
    if why := plugin_loaded(proc, args.plugin):
        raise Failure(why)
    if proc.returncode != 0 or "STRAIGHT_FEED" not in proc.stdout:
        raise Failure(f"rs274 -p: exit {proc.returncode}: {proc.stderr.strip()[:300]}")
    data = journal.read_bytes()
    payloads = records_of(data)
    header, blocks = payloads[0], payloads[1:]
    if not header.startswith(b"nckit-journal 1 ") or b"#500=41 #501=0 #502=40" not in header:
        raise Failure(f"the header does not keep #500-#502 as the run found them: {header!r}")
    probe = run([args.nckit, "restart", str(program), "--block", "999999999", "--machine", str(REPO / MACHINE),
                 "--vars", str(start_vars)], work)
    counted = int(probe.stderr.split("(")[1].split(" blocks run")[0])
    if len(blocks) != counted:
        raise Failure(f"the journal records {len(blocks)} blocks, nckit counts {counted}")
    for i, b in enumerate(blocks, start=1):
        if not b.startswith(f"B {i} ".encode()):
            raise Failure(f"record {i} does not number its block {i}: {b!r}")
    if "parts_counter" in name and not any(b" #500=42" in b for b in blocks):
        raise Failure("no record carries the block's #500 = #500 + 1")
    original = moves(args.nckit, program, start_vars, work)
    live = work / "live.vars"
    cuts = sorted({1, len(blocks) // 3, len(blocks) // 2, (2 * len(blocks)) // 3, len(blocks) - 1} - {0})
    lines = data.split(b"\n")
    for k in cuts:
        cut = work / f"cut{k}.journal"
        cut.write_bytes(b"\n".join(lines[: k + 1]) + b"\n")
        live.write_text("#500 = 999\n")  # the live file is not what the search starts from
        out = work / "r.ngc"
        proc = run([args.nckit, "restart", str(program), "--journal", str(cut), "--json", "-o", str(out), "--machine",
                    str(REPO / MACHINE), "--vars", str(live)], work)
        if proc.returncode != 0:
            raise Failure(f"restart from the journal cut after block {k}: {proc.stderr.strip()}")
        report = json.loads(proc.stdout)
        if report["block"] != k + 1 or report["journal"]["last_block"] != k:
            raise Failure(f"cut after block {k}: restart targets block {report['block']}")
        rest = [r for r in moves(args.nckit, out, live, work) if r["line"] >= report["rest_line"]]
        expected = original[report["first_record"]:]
        if len(rest) != len(expected):
            raise Failure(f"cut after block {k}: {len(rest)} records after the approach, the original has "
                          f"{len(expected)}")
        for i, (o, r) in enumerate(zip(expected, rest)):
            if diff := differ(o, r):
                raise Failure(f"cut after block {k}, record {report['first_record'] + i}: {diff}")
    proc = run([args.nckit, "restart", str(program), "--journal", str(journal), "--machine", str(REPO / MACHINE),
                "--vars", str(live)], work)
    if proc.returncode != 2 or "nothing is left to restart" not in proc.stderr:
        raise Failure(f"the finished run's journal is not refused as complete: {proc.stderr.strip()}")
    return f"{len(blocks)} blocks journaled, restarts after blocks {cuts} checked"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--rs274", default="rs274")
    args = ap.parse_args()
    return run_each(PROGRAMS, "nckit-plugin-journal-", lambda name, work: check_program(args, name, work))


if __name__ == "__main__":
    sys.exit(main())
