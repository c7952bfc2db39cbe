#!/usr/bin/env python3
"""Side-by-side test of `nckit moves --json` against LinuxCNC's standalone interpreter `rs274`.

For every program (`NN_name.ngc`) it runs `rs274 -g` and `nckit moves --json`, turns rs274's
canonical calls into absolute machine positions in mm, and compares the motions in order: kind,
end point on every axis both sides have (X Y Z, and A B C on machines that have them), each arc's
centre on the two plane axes and its direction, the feed rate of feeds and arcs (mm/min; under
G95 mm/rev x the commanded rpm; not under G96, where it follows X), and the source line of each
motion. Dwells, I/O events and the feed of rapids are not compared. How rs274's output is read:
rs274_output.py; the comments in a program's first lines that set up its run: program_setup.py.

Expand mode (`--expand`), for programs rs274 cannot read (Fanuc Custom Macro B: `NN_name.nc` as
well as `NN_name.ngc`): `nckit expand PROGRAM -o expanded.ngc` writes the program out as plain
G-code (one move per block, absolute machine coordinates in mm, radius mode G8 on a diameter-mode
lathe); rs274 runs that as the reference, and `nckit moves --json` runs the ORIGINAL program.
Kinds, end points, arc centres and directions, and feeds are compared as above; source lines are
not (the expanded program's lines are not the original's: each of its blocks names the source
line in a comment, which the messages show). Called programs are looked up in `--library DIR`
(default: the programs folder's `library/` when there is one); retained variables #500-#999 are
kept in a scratch file, never beside the machine file. rs274 gets a tool table of the tools the
expanded program selects, all offsets zero (alone it knows only low tool numbers: a lathe's T0101
comes out as T101).

Exit status: 0 when every program matches, 1 otherwise (and when rs274 or nckit is missing).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

# Other tests use these as compare_linuxcnc.NAME, hence the names not used here.
from nckit_moves import nckit_motion, run_nckit  # noqa: F401
from program_setup import DEFAULT_MILL, Setup, load_machine, setup_of  # noqa: F401
from rs274_output import (  # noqa: F401
    ALL_AXES, COMPARED_AXES, COMPARED_KINDS, KNOWN_KINDS, Motion, ProgramError, annotate,
    check_reference, inch_tool_table, parse_rs274, run_rs274, tool_table_for,
)

REPO = Path(__file__).resolve().parents[2]
DEFAULT_NCKIT = REPO / "build" / "release" / "src" / "nckit"
DEFAULT_MACHINES = REPO / "examples" / "machines"

# ----------------------------------------------------------------------------------------------
# Comparison

def source_line(lines: list[str], number) -> str:
    if isinstance(number, int) and 1 <= number <= len(lines):
        return f"line {number} `{lines[number - 1].strip()}`"
    return f"line {number}"


def compare(ref: list[Motion], got: list[Motion], machine_axes: set[str],
            src: list[str], check_lines: bool, check_feed: bool,
            got_src: list[str] | None = None) -> str | None:
    """The first difference, or None. `src` holds the lines of the program rs274 ran, `got_src`
    those of the one nckit ran when it is another (expand mode)."""
    if got_src is None:
        got_src = src
    compared = [a for a in COMPARED_AXES if a in machine_axes]
    for i, (r, g) in enumerate(zip(ref, got), start=1):
        where = f"motion {i} of {len(ref)}, " + (source_line(src, r.line) if r.line
                                                 else source_line(got_src, g.line))
        both = f"\n    nckit:  {g.text}\n    rs274:  {r.text}"
        if set(g.end) != machine_axes:
            return (f"{where}: nckit `end` has axes {sorted(g.end)}, "
                    f"machine has {sorted(machine_axes)}")
        if r.kind != g.kind:
            return f"{where}: kind nckit {g.kind} vs rs274 {r.kind}{both}"
        for a in compared:
            if abs(g.end[a] - r.end[a]) > r.tol[a]:
                return (f"{where}: end {a} nckit {g.end[a]:.6f} vs rs274 {r.end[a]:.6f} "
                        f"(diff {g.end[a] - r.end[a]:+.6f}, tol {r.tol[a]:.6f}){both}")
        for a in COMPARED_AXES:
            if a not in machine_axes and abs(r.end[a]) > r.tol[a]:
                return (f"{where}: rs274 moves {a} to {r.end[a]:.4f} but the nckit machine has no "
                        f"{a} axis (program bug){both}")
        if r.kind == "arc":
            for a in r.plane:
                if a not in g.center:
                    return f"{where}: nckit arc centre lacks {a}{both}"
                if abs(g.center[a] - r.center[a]) > r.tol[a]:
                    return (f"{where}: arc centre {a} nckit {g.center[a]:.6f} vs rs274 "
                            f"{r.center[a]:.6f} (diff {g.center[a] - r.center[a]:+.6f}){both}")
            if g.direction != r.direction:
                return f"{where}: arc dir nckit {g.direction} vs rs274 {r.direction}{both}"
        if check_feed and r.feed_mm_min is not None and (
                g.feed_mm_min is None or abs(g.feed_mm_min - r.feed_mm_min) > r.feed_tol):
            return (f"{where}: feed_mm_min nckit {g.feed_mm_min} vs rs274 "
                    f"{r.feed_mm_min:.4f}{both}")
        if check_lines and r.line is not None and g.line != r.line:
            return f"{where}: source line nckit {g.line} vs rs274 {r.line}{both}"
    if len(ref) != len(got):
        more, name = (ref, "rs274") if len(ref) > len(got) else (got, "nckit")
        extra = more[min(len(ref), len(got))]
        return (f"motion count nckit {len(got)} vs rs274 {len(ref)}; first extra {name} motion "
                f"({source_line(src if more is ref else got_src, extra.line)}): {extra.text}")
    return None


def drop_zero_length(motions: list[Motion], tol: float = 1e-6) -> list[Motion]:
    """Straight moves that go nowhere (e.g. G91 G28 Z0's intermediate point); arcs stay (full
    circles end where they start)."""
    out, prev = [], None
    for mo in motions:
        if (mo.kind != "arc" and prev is not None
                and all(abs(mo.end[a] - prev[a]) <= tol for a in mo.end if a in prev)):
            continue
        out.append(mo)
        prev = mo.end
    return out


@dataclass
class Reference:
    motions: list[Motion]
    machine: dict
    setup: Setup


def reference(program: Path, rs274: str, machines_dir: Path, workdir: Path,
              timeout: float, setup: Setup | None = None, radius_program: bool = False,
              block_delete: bool | None = None, tools: bool = False) -> Reference:
    """rs274's motions for a program. `setup` defaults to the program's own `nckit-...:`
    comments; `block_delete` (default: the setup's) is what rs274 gets; `radius_program`: see
    parse_rs274; `tools`: rs274 gets a tool table of the tools the program selects."""
    if setup is None:
        setup = setup_of(program, machines_dir)
    if block_delete is None:
        block_delete = setup.block_delete
    if setup.machine_file is not None and not setup.machine_file.is_file():
        raise ProgramError(f"machine file {setup.machine_file} does not exist")
    machine = load_machine(setup.machine_file) if setup.machine_file else DEFAULT_MILL
    table = tool_table_for(program, workdir) if tools else None
    if setup.tools_file is not None:
        table = inch_tool_table(setup.tools_file, workdir)
    plain = run_rs274(rs274, program, block_delete, workdir, timeout, table)
    tagged_path = workdir / ("tagged_" + program.name)
    tagged_path.write_text(annotate(program.read_text(encoding="utf-8", errors="replace")))
    if setup.tools_file is not None:
        table = inch_tool_table(setup.tools_file, workdir)  # rs274 rewrites its tool table at exit
    elif table is not None:
        table = tool_table_for(program, workdir)
    tagged = run_rs274(rs274, tagged_path, block_delete, workdir, timeout, table)
    motions = parse_rs274(tagged, machine["diameter_mode"], radius_program)
    untagged = parse_rs274(plain, machine["diameter_mode"], radius_program)
    if [(m.kind, m.end, m.center, m.direction) for m in motions] != \
       [(m.kind, m.end, m.center, m.direction) for m in untagged]:
        raise ProgramError("harness: the line-number comments changed rs274's motions")
    check_reference(motions, machine)
    return Reference(motions, machine, setup)


def expected_json(ref: Reference) -> str:
    """rs274's motions written the way `nckit moves --json` should write them."""
    axes = list(ref.machine["axes"]) or list(COMPARED_AXES)
    rows = []
    for mo in ref.motions:
        rec = {"line": mo.line, "kind": mo.kind,
               "end": {a: round(mo.end[a], 6) for a in axes if a in mo.end}}
        if mo.kind == "arc":
            rec["center"] = {a: round(mo.center[a], 6) for a in mo.plane}
            rec["dir"] = mo.direction
        rows.append(json.dumps(rec))
    return "\n".join(rows)


def run_program(program: Path, args, workdir: Path) -> tuple[bool, str]:
    if args.expand:
        return run_expanded_program(program, args, workdir)
    try:
        ref = reference(program, args.rs274, args.machines, workdir, args.timeout)
    except ProgramError as e:
        return False, f"FAIL {program.stem}: program: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: rs274 timed out"
    src = program.read_text(encoding="utf-8", errors="replace").splitlines()
    return compare_program(program, ref, program, src, args, workdir, not args.ignore_lines)


def compare_program(program: Path, ref: Reference, reference_program: Path, src: list[str], args,
                    workdir: Path, check_lines: bool,
                    extra: list[str] | None = None) -> tuple[bool, str]:
    """`nckit moves --json` of `program` against the rs274 motions `ref` (of
    `reference_program`, whose lines are `src`); `extra`: more nckit options."""
    try:
        records = run_nckit(args.nckit, program, ref.setup, workdir, args.timeout, extra)
        got = [nckit_motion(r, i) for i, r in enumerate(records, start=1)
               if r["kind"] in COMPARED_KINDS]
    except AssertionError as e:
        return False, f"FAIL {program.stem}: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: nckit timed out"
    machine_axes = set(ref.machine["axes"]) or (set(got[0].end) if got else {"X", "Y", "Z"})
    motions = ref.motions
    if args.skip_zero_length:
        motions, got = drop_zero_length(motions), drop_zero_length(got)
    got_src = None
    if reference_program != program:
        got_src = program.read_text(encoding="utf-8", errors="replace").splitlines()
    diff = compare(motions, got, machine_axes, src, check_lines, args.feed, got_src)
    if diff:
        if len(motions) != len(got) and not diff.startswith("motion count"):
            diff += f"\n    (motion count nckit {len(got)} vs rs274 {len(motions)})"
        if reference_program != program:
            diff += (f"\n    (rs274 ran {reference_program.name}, the expanded program: its "
                     f"lines end in a comment naming the source line)")
        return False, f"FAIL {program.stem}: {diff}"
    return True, f"ok {program.stem} ({len(motions)} moves)"


# ----------------------------------------------------------------------------------------------
# Expand mode: rs274 runs what `nckit expand` wrote, nckit the original program

def nckit_extra(args, workdir: Path, purpose: str) -> list[str]:
    """Options both `nckit expand` and `nckit moves` get in expand mode: the library folder, and
    a scratch file for retained variables (one per run, so that neither run sees what the other
    left, and nothing is written beside the machine file)."""
    extra = ["--vars", str(workdir / f"{purpose}.vars")]
    if args.library is not None:
        extra += ["--library", str(args.library)]
    if args.max_blocks is not None:
        extra += ["--max-blocks", str(args.max_blocks)]
    return extra


def expand_program(program: Path, setup: Setup, args, workdir: Path) -> Path:
    """`nckit expand` of the program into workdir/expanded.ngc (AssertionError when it fails)."""
    out = workdir / "expanded.ngc"
    cmd = [args.nckit, "expand", str(program)]
    if setup.machine_file is not None:
        cmd += ["--machine", str(setup.machine_file)]
    if setup.block_delete:
        cmd.append("--block-delete")
    cmd += nckit_extra(args, workdir, "expand") + ["-o", str(out)]
    proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=args.timeout)
    if proc.returncode != 0:
        err = " | ".join(proc.stderr.strip().splitlines()[:3]) or "(no message)"
        raise AssertionError(f"nckit expand exit status {proc.returncode}: {err}")
    if not out.is_file():
        raise AssertionError(f"nckit expand exited 0 but wrote no {out.name}")
    return out


def expanded_reference(program: Path, args, workdir: Path) -> tuple[Reference, Path]:
    """rs274's motions for the expanded program. ProgramError: the original program's setup is
    wrong; AssertionError: nckit expand failed or rs274 rejects what it wrote."""
    setup = setup_of(program, args.machines)
    if setup.machine_file is not None and not setup.machine_file.is_file():
        raise ProgramError(f"machine file {setup.machine_file} does not exist")
    expanded = expand_program(program, setup, args, workdir)
    try:
        # The expanded program has no deleted blocks left, and writes X as a radius (G8).
        ref = reference(expanded, args.rs274, args.machines, workdir, args.timeout, setup=setup,
                        radius_program=True, block_delete=False, tools=True)
    except ProgramError as e:
        raise AssertionError(f"rs274 on the expanded program: {e}") from None
    return ref, expanded


def run_expanded_program(program: Path, args, workdir: Path) -> tuple[bool, str]:
    try:
        ref, expanded = expanded_reference(program, args, workdir)
    except ProgramError as e:
        return False, f"FAIL {program.stem}: program: {e}"
    except AssertionError as e:
        return False, f"FAIL {program.stem}: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: nckit expand or rs274 timed out"
    if args.keep_expanded is not None:
        args.keep_expanded.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(expanded, args.keep_expanded / (program.stem + ".ngc"))
    # Source lines are not compared: rs274's are the expanded program's, nckit's the original's.
    src = expanded.read_text(encoding="utf-8", errors="replace").splitlines()
    return compare_program(program, ref, expanded, src, args, workdir, False,
                           nckit_extra(args, workdir, "moves"))


def select_programs(directory: Path, names: list[str], patterns=("*.ngc",)) -> list[Path]:
    programs = sorted({p for pattern in patterns for p in directory.glob(pattern)})
    if not names:
        return programs
    chosen = []
    for name in names:
        hits = [p for p in programs if p.name == name or p.stem == name
                or p.stem.startswith(name + "_")]
        if not hits:
            sys.exit(f"error: no program {name!r} in {directory}")
        chosen += [h for h in hits if h not in chosen]
    return chosen


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="programs to run (file name, stem or NN prefix)")
    ap.add_argument("--nckit", default=str(DEFAULT_NCKIT), help="nckit binary (%(default)s)")
    ap.add_argument("--rs274", default=None, help="LinuxCNC rs274 binary (default: from PATH)")
    ap.add_argument("--programs", type=Path, default=Path(__file__).resolve().parent,
                    help="folder of NN_name.ngc programs (NN_name.nc too with --expand; "
                         "default: this script's folder)")
    ap.add_argument("--machines", type=Path, default=DEFAULT_MACHINES,
                    help="folder the nckit-machine comments refer to (%(default)s)")
    ap.add_argument("--expected", action="store_true",
                    help="print rs274's motions as nckit-style JSON lines instead of comparing")
    ap.add_argument("--ignore-lines", action="store_true", help="do not compare source lines")
    ap.add_argument("--no-feed", dest="feed", action="store_false",
                    help="do not compare feed_mm_min of feeds and arcs (G95: mm/rev x rpm)")
    ap.add_argument("--skip-zero-length", action="store_true",
                    help="drop straight moves of zero length on both sides before comparing")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per run (%(default)s)")
    ap.add_argument("--expand", action="store_true",
                    help="rs274 runs `nckit expand PROGRAM` (macro programs: *.nc and *.ngc), "
                         "nckit the original; source lines are not compared")
    ap.add_argument("--library", type=Path, default=None,
                    help="expand mode: folder of called programs (default: PROGRAMS/library "
                         "when it exists)")
    ap.add_argument("--max-blocks", type=int, default=None,
                    help="expand mode: nckit's --max-blocks (default: nckit's own budget)")
    ap.add_argument("--keep-expanded", type=Path, default=None, metavar="DIR",
                    help="expand mode: keep each expanded program as DIR/STEM.ngc")
    args = ap.parse_args()

    rs274 = args.rs274 or shutil.which("rs274")
    if not rs274 or not os.access(rs274, os.X_OK):
        print(f"error: LinuxCNC's rs274 not found ({args.rs274 or 'not on PATH'}); "
              f"run scripts/deps.sh to install linuxcnc-uspace", file=sys.stderr)
        return 1
    args.rs274 = rs274
    # nckit and rs274 run in scratch folders: every path handed to them must be absolute.
    args.programs, args.machines = args.programs.resolve(), args.machines.resolve()
    if os.sep in args.nckit:
        args.nckit = str(Path(args.nckit).resolve())
    else:
        args.nckit = shutil.which(args.nckit) or args.nckit
    if args.expand:
        if args.library is None and (args.programs / "library").is_dir():
            args.library = args.programs / "library"
        if args.library is not None:
            args.library = args.library.resolve()
            if not args.library.is_dir():
                print(f"error: library folder {args.library} does not exist", file=sys.stderr)
                return 1
        if args.keep_expanded is not None:
            args.keep_expanded = args.keep_expanded.resolve()
    if (args.expand or not args.expected) and not os.access(args.nckit, os.X_OK):
        print(f"error: nckit binary {args.nckit} not found or not executable; build it first "
              f"(make build) or pass --nckit", file=sys.stderr)
        return 1
    patterns = ("*.nc", "*.ngc") if args.expand else ("*.ngc",)
    programs = select_programs(args.programs, args.names, patterns)
    if not programs:
        print(f"error: no {' or '.join(patterns)} programs in {args.programs}", file=sys.stderr)
        return 1

    passed = failed = 0
    with tempfile.TemporaryDirectory(prefix="nckit-linuxcnc-") as tmp:
        for program in programs:
            workdir = Path(tempfile.mkdtemp(dir=tmp))
            if args.expected:
                try:
                    if args.expand:
                        ref, _ = expanded_reference(program, args, workdir)
                    else:
                        ref = reference(program, args.rs274, args.machines, workdir,
                                        args.timeout)
                except ProgramError as e:
                    print(f"FAIL {program.stem}: program: {e}", file=sys.stderr)
                    failed += 1
                    continue
                except AssertionError as e:
                    print(f"FAIL {program.stem}: {e}", file=sys.stderr)
                    failed += 1
                    continue
                print(f"# {program.name}")
                print(expected_json(ref))
                passed += 1
                continue
            ok, message = run_program(program, args, workdir)
            print(message, flush=True)
            passed, failed = passed + ok, failed + (not ok)
    print(f"{passed} passed, {failed} failed", file=sys.stderr if args.expected else sys.stdout)
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
