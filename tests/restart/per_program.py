"""What the restart tests beside this file share: a failure of one program's checks, and the loop
that checks each program in a folder of its own and prints one line per program and a total."""
from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Callable, Sequence


class Failure(Exception):
    pass


def run_each(programs: Sequence, prefix: str, check: Callable[[object, Path], str]) -> int:
    """check(program, work folder) returns its summary or raises Failure; returns the exit status.
    A program is its path, or a tuple whose first item is its path."""
    failed = 0
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        for program in programs:
            name = program[0] if isinstance(program, tuple) else program
            work = Path(tempfile.mkdtemp(dir=tmp))
            try:
                print(f"ok {name}: {check(program, work)}", flush=True)
            except Failure as e:
                print(f"FAIL {name}: {e}", flush=True)
                failed += 1
    print(f"{len(programs) - failed} passed, {failed} failed")
    return 1 if failed else 0
