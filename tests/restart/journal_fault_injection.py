#!/usr/bin/env python3
"""Run journal under fault injection: killed runs and torn journals restart right.

For each program it records the original run (`nckit moves --json`), then:

1. Kills runs: starts `nckit steps PROGRAM --journal J --journal-fsync-ms 0` (or `servo` on the
   servo mill) and sends SIGKILL once the journal has grown past a random byte count (or, in a
   third of the runs, after a random share of a clean run's wall time), so the process dies in
   the middle of its run at a place the test does not choose. A run that ends before the kill
   is a run whose journal records every block.
2. Tears the journal: for the last complete record of each killed journal, the journal cut at
   every byte offset inside that record, and the record with one byte flipped.
3. For every journal: reads it independently (records are `PAYLOAD *CRC32\\n`, CRC-32 as
   zlib's), finds the last record whose checksum holds and numbers its block right, and runs
   `nckit restart PROGRAM --journal J --json -o r.ngc`. The restart must target the block after
   that record (`block`, `journal.last_block`), and the restart program's moves after its
   approach must equal the original's from that block on (1e-9 mm, the comparison of
   restart_every_block.py). A journal of a finished run must be refused as
   `restart-run-complete`.
4. For the program with retained counters (#500-#502): runs the restart program with
   `nckit moves --save-vars` from the retained values of the killed run's start, and the
   variables must end as a full uninterrupted run leaves them (no part counted twice).

No timing enters a verdict: the kill moments only decide where the runs stop.
Exit status: 0 when every journal restarts right, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import signal
import subprocess
import sys
import time
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(REPO / "tests" / "macro_programs"))
from expand_roundtrip import differ  # noqa: E402
from per_program import Failure, run_each  # noqa: E402

# (program, machine, verb that runs the machine)
PROGRAMS = [
    ("examples/restart/parts_counter.nc", "examples/machines/mill.toml", "steps"),
    ("examples/restart/bolt_circle_loop.nc", "examples/machines/mill.toml", "steps"),
    ("examples/01_mill_pocket.ngc", "examples/machines/servo_mill.toml", "servo"),
    ("examples/02_lathe_shaft.ngc", "examples/machines/lathe.toml", "steps"),
]
RETAINED_START = "#500 = 41\n#501 = 0\n#502 = 40\n"


def run(cmd: list[str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)


def machine_args(machine: str, vars_file: Path) -> list[str]:
    return ["--machine", str(REPO / machine), "--vars", str(vars_file)]


def last_complete_block(data: bytes) -> int | None:
    """Block number of the last trusted record (0: header only); None: no complete header."""
    block, header = 0, False
    for line in data.split(b"\n")[:-1]:  # the piece after the last newline is torn
        payload, sep, crc = line.rpartition(b" *")
        # Eight hex digits exactly: int(..., 16) would also take " 5724889" (a flipped '0').
        if not sep or len(crc) != 8 or not all(c in b"0123456789abcdefABCDEF" for c in crc):
            break
        try:
            if zlib.crc32(payload) != int(crc, 16):
                break
        except ValueError:
            break
        words = payload.split(b" ")
        if not header:
            if words[0] != b"nckit-journal":
                break
            header = True
            continue
        if words[0] != b"B" or int(words[1]) != block + 1:
            break
        block += 1
    return block if header else None


def record_spans(data: bytes) -> list[tuple[int, int]]:
    """(start, end) byte offsets of every complete line, newline included."""
    spans, start = [], 0
    while True:
        end = data.find(b"\n", start)
        if end < 0:
            return spans
        spans.append((start, end + 1))
        start = end + 1


class Program:
    def __init__(self, args, name: str, machine: str, verb: str, work: Path):
        self.args, self.name, self.machine, self.verb, self.work = args, name, machine, verb, work
        self.path = REPO / name
        self.start_vars = work / "start.vars"
        self.start_vars.write_text(RETAINED_START)
        proc = run([args.nckit, "moves", str(self.path), "--json", *machine_args(machine, self.start_vars)], work)
        if proc.returncode != 0:
            raise Failure(f"nckit moves: {proc.stderr.strip()}")
        self.original = [json.loads(t) for t in proc.stdout.splitlines() if t.strip()]
        full = work / "full.vars"
        full.write_text(RETAINED_START)
        proc = run([args.nckit, "moves", str(self.path), "--save-vars", *machine_args(machine, full)], work)
        if proc.returncode != 0:
            raise Failure(f"nckit moves --save-vars: {proc.stderr.strip()}")
        self.full_vars = full.read_text()
        self.clean_s = self.timed_run(work / "clean.journal")

    def command(self, journal: Path) -> list[str]:
        out = ["-o", "/dev/null"] if self.verb == "steps" else []
        return [self.args.nckit, self.verb, str(self.path), "--journal", str(journal), "--journal-fsync-ms", "0",
                "--quiet", *out, *machine_args(self.machine, self.start_vars)]

    def timed_run(self, journal: Path) -> float:
        t0 = time.monotonic()
        proc = run(self.command(journal), self.work)
        if proc.returncode != 0:
            raise Failure(f"nckit {self.verb} --journal: exit {proc.returncode}: {proc.stderr.strip()}")
        return time.monotonic() - t0

    def killed_run(self, journal: Path, rng: random.Random) -> bool:
        """Runs with a journal and kills it; True when it was killed before it ended."""
        full_size = (self.work / "clean.journal").stat().st_size
        by_size = rng.random() < 2 / 3
        limit = rng.randrange(1, full_size) if by_size else rng.uniform(0, self.clean_s)
        proc = subprocess.Popen(self.command(journal), cwd=self.work, stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        t0 = time.monotonic()
        while proc.poll() is None:
            size = journal.stat().st_size if journal.exists() else 0
            if (by_size and size >= limit) or (not by_size and time.monotonic() - t0 >= limit):
                proc.send_signal(signal.SIGKILL)
                break
            time.sleep(0.0005)
        return proc.wait() == -signal.SIGKILL

    def check_restart(self, journal: Path, what: str, same_as: tuple | None = None) -> tuple:
        """Restarts from `journal`: ('restarted', report, program text), ('complete',) or ('empty',).

        With `same_as` (an earlier answer for the same trusted records) the restart program and
        report must equal that one, which was compared with the original move by move."""
        expected_last = last_complete_block(journal.read_bytes())
        out = self.work / "r.ngc"
        live = self.work / "live.vars"
        live.write_text("#500 = 999\n")  # the live file is not what the search starts from
        proc = run([self.args.nckit, "restart", str(self.path), "--journal", str(journal), "--json", "-o", str(out),
                    *machine_args(self.machine, self.work / "live.vars")], self.work)
        if expected_last is None:
            if proc.returncode != 2 or "no complete first record" not in proc.stderr:
                raise Failure(f"{what}: a journal without a header is not refused: {proc.stderr.strip()}")
            return ("empty",)
        if proc.returncode != 0:
            if proc.returncode == 2 and "nothing is left to restart" in proc.stderr:
                if expected_last != self.blocks:
                    raise Failure(f"{what}: refused as complete after block {expected_last} of {self.blocks}")
                return ("complete",)
            raise Failure(f"{what}: exit {proc.returncode}: {proc.stderr.strip()}")
        report = json.loads(proc.stdout)
        if report["journal"]["records"] != expected_last or report["block"] != expected_last + 1:
            raise Failure(f"{what}: restart at block {report['block']} (journal {report['journal']}), "
                          f"the last complete record is block {expected_last}")
        text = out.read_text()
        if same_as is not None and same_as[0] == "restarted":
            del report["journal"]["ignored_bytes"]
            if text != same_as[2] or report != same_as[1]:
                raise Failure(f"{what}: another restart than from the journal cut before the record")
            return same_as
        rest = self.moves(out, live)
        rest = [r for r in rest if r["line"] >= report["rest_line"]]
        expected = self.original[report["first_record"]:]
        if len(rest) != len(expected):
            raise Failure(f"{what}: {len(rest)} records after the approach, the original has {len(expected)}")
        for i, (o, r) in enumerate(zip(expected, rest)):
            diff = differ(o, r)
            if diff:
                raise Failure(f"{what}: record {report['first_record'] + i}: {diff}")
        if self.name.endswith("parts_counter.nc"):
            finished = self.work / "restarted.vars"
            finished.write_text("#500 = 777\n")  # whatever the control held: the preamble sets them
            proc = run([self.args.nckit, "moves", str(out), "--save-vars", *machine_args(self.machine, finished)],
                       self.work)
            if proc.returncode != 0:
                raise Failure(f"{what}: moves --save-vars of the restart program: {proc.stderr.strip()}")
            if finished.read_text() != self.full_vars:
                raise Failure(f"{what}: retained variables end as\n{finished.read_text()}not as a full run's\n"
                              f"{self.full_vars}")
        del report["journal"]["ignored_bytes"]
        return ("restarted", report, text)

    def moves(self, program: Path, vars_file: Path) -> list[dict]:
        proc = run([self.args.nckit, "moves", str(program), "--json", *machine_args(self.machine, vars_file)],
                   self.work)
        if proc.returncode != 0:
            raise Failure(f"nckit moves {program.name}: {proc.stderr.strip()}")
        return [json.loads(t) for t in proc.stdout.splitlines() if t.strip()]


def check_program(args, rng: random.Random, name: str, machine: str, verb: str, work: Path) -> str:
    p = Program(args, name, machine, verb, work)
    p.blocks = last_complete_block((work / "clean.journal").read_bytes())
    if not p.blocks:
        raise Failure("the clean run's journal has no block")
    outcomes: dict[str, int] = {}
    killed = 0
    journal = work / "j.journal"
    for k in range(args.runs):
        if journal.exists():
            journal.unlink()
        killed += p.killed_run(journal, rng)
        if not journal.exists():
            outcomes["not started"] = outcomes.get("not started", 0) + 1
            continue
        data = journal.read_bytes()
        result = p.check_restart(journal, f"run {k}")[0]
        outcomes[result] = outcomes.get(result, 0) + 1
        spans = record_spans(data)
        if k < args.torn_runs and len(spans) > 1:
            start, end = spans[-1]
            torn = work / "torn.journal"
            torn.write_bytes(data[:start])
            before = p.check_restart(torn, f"run {k} cut before its last record")
            for cut in range(start + 1, end):
                torn.write_bytes(data[:cut])
                p.check_restart(torn, f"run {k} cut at byte {cut}", before)
            flipped = bytearray(data[:end])
            at = rng.randrange(start, end - 1)
            flipped[at] ^= 1 << rng.randrange(7)
            torn.write_bytes(bytes(flipped))
            # A flip that leaves the record whole (bit 5 of a checksum letter: 'a' to 'A', the
            # same hex digit) is no damage: that journal restarts after the record, checked
            # against the original like any other, not against the one cut before it.
            damaged = last_complete_block(bytes(flipped)) == last_complete_block(data[:start])
            p.check_restart(torn, f"run {k} byte {at} flipped", before if damaged else None)
    if killed == 0:
        raise Failure("no run was killed before its end")
    return f"{p.blocks} blocks, {args.runs} runs, {killed} killed, restarts: {outcomes}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--runs", type=int, default=50, help="killed runs per program (%(default)s)")
    ap.add_argument("--torn-runs", type=int, default=2,
                    help="killed runs per program whose last record is also cut at every byte (%(default)s)")
    ap.add_argument("--seed", type=int, default=None, help="random seed (default: new each run, printed)")
    args = ap.parse_args()
    seed = args.seed if args.seed is not None else random.randrange(1 << 30)
    print(f"seed {seed}", flush=True)
    rng = random.Random(seed)
    return run_each(PROGRAMS, "nckit-journal-", lambda p, work: check_program(args, rng, *p, work))


if __name__ == "__main__":
    sys.exit(main())
