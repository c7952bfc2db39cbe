#!/usr/bin/env python3
"""Side-by-side test of cutter radius compensation against LinuxCNC's rs274.

Runs tests/programs/compare_linuxcnc.py's comparison (every motion's kind, end point, arc centre
and direction, feed and source line) on the programs of this folder (arguments as for that
script). A program NN_name.ngc with a tool table NN_name.tbl beside it runs with that table on
both sides:
- nckit reads it (LinuxCNC's tool.tbl format, values in mm) with `--tools FILE`;
- standalone rs274 reads tool-table lengths and diameters as inches whatever the program's
  units, so it gets a copy with every length and diameter divided by 25.4.

`--dialect linuxcnc` runs nckit in that dialect (its own corner construction and checks, which
must give rs274's moves on these programs too); the default is nckit's default, Fanuc.

Exit status: 0 when every program matches, 1 otherwise.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "programs"))
import compare_linuxcnc as cl  # noqa: E402

# Words of a tool.tbl row that hold lengths (Z and the other axis offsets, D the diameter).
LENGTH_WORD = re.compile(r"\b([XYZUVWD])\s*([-+]?\d*\.?\d+)", re.IGNORECASE)


def inch_copy(table: Path, workdir: Path) -> Path:
    """The tool table with every length and diameter in inches, for standalone rs274."""
    rows = []
    for text in table.read_text(encoding="utf-8").splitlines():
        body, sep, comment = text.partition(";")
        body = LENGTH_WORD.sub(lambda m: f"{m.group(1)}{float(m.group(2)) / 25.4:.8f}", body)
        rows.append(body + sep + comment)
    path = workdir / "tools-inch.tbl"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


def table_of(program: Path) -> Path | None:
    """The program's tool table: NN_name.tbl beside NN_name.ngc (the rs274 run gets a tagged copy
    named tagged_NN_name.ngc in a scratch folder, so the name is what counts)."""
    name = program.name.removeprefix("tagged_")
    table = HERE / (Path(name).stem + ".tbl")
    return table if table.is_file() else None


def main() -> int:
    run_rs274 = cl.run_rs274
    run_nckit = cl.run_nckit

    def rs274_with_table(rs274, program, block_delete, workdir, timeout, tool_table=None):
        table = table_of(Path(program))
        # A fresh copy for every run: rs274 rewrites its tool table at exit.
        copy = inch_copy(table, Path(workdir)) if table is not None else tool_table
        return run_rs274(rs274, program, block_delete, workdir, timeout, copy)

    argv = sys.argv[1:]
    dialect = []
    if "--dialect" in argv:
        at = argv.index("--dialect")
        dialect = ["--dialect", argv[at + 1]]
        del argv[at:at + 2]

    def nckit_with_table(nckit, program, setup, workdir, timeout, extra=None):
        table = table_of(Path(program))
        tools = ["--tools", str(table)] if table is not None else []
        return run_nckit(nckit, program, setup, workdir, timeout, [*tools, *dialect, *(extra or [])])

    cl.run_rs274 = rs274_with_table
    cl.run_nckit = nckit_with_table
    sys.argv = [sys.argv[0], "--programs", str(HERE), *argv]
    return cl.main()


if __name__ == "__main__":
    sys.exit(main())
