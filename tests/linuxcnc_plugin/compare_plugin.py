#!/usr/bin/env python3
"""nckit's LinuxCNC interpreter plug-in against `nckit moves`: the same program, two ways.

For every program given (tests/programs/NN_name.ngc, tests/macro_programs/NN_name.nc, ...) it runs
LinuxCNC's standalone interpreter driver with the plug-in,

    rs274 -p /abs/libnckit_linuxcnc.so -i plugin.ini [-b] -g PROGRAM

and `nckit moves PROGRAM --json` with the same machine file, library folder and block delete
switch, and compares the motions in order: kind (rapid, feed, arc, spindle-synchronised), end
point on every axis, each arc's centre and direction, the feed (mm/min; G95 as mm/rev x rpm) and
the source line. rs274's canonical calls are turned into machine mm by
tests/programs/compare_linuxcnc.py (program units and the G5x and G92 offsets the calls set), so
the plug-in's units and offsets are checked along with the positions; the tolerance is the 4
decimals rs274 prints (1e-4 mm, wider for inch programs).

Every rs274 run must print `using custom interpreter '<plug-in>'`: when LinuxCNC cannot load a
plug-in it says so once and runs its own interpreter instead, which would compare LinuxCNC's
interpreter with nckit (and fail on Macro B) rather than test the plug-in.

The INI the plug-in reads ([NCKIT] section): MACHINE from the program's `( nckit-machine: F )`
comment (resolved against examples/machines/), LIBRARY from --library, RETAINED a scratch file
per run (both sides start with #500-#999 vacant), LINE_COMMENTS = 1 (a COMMENT("nckit-line N")
before each source line's motions, which carries the line into rs274's output); and [EMCIO]
TOOL_TABLE, LinuxCNC's own key, from the program's `( nckit-tools: F )` comment (the table
`nckit moves --tools` gets).

Exit status: 0 when every program matches, 1 otherwise (and when rs274, nckit or the plug-in is
missing).
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(REPO / "tests" / "programs"))
import compare_linuxcnc as cl  # noqa: E402  (the rs274 reader and the comparison)

CUSTOM = "using custom interpreter"


def write_ini(path: Path, setup: cl.Setup, library: Path | None, retained: Path) -> None:
    lines = ["# nckit plug-in settings for one comparison run", "[NCKIT]"]
    if setup.machine_file is not None:
        lines.append(f"MACHINE = {setup.machine_file}")
    if library is not None:
        lines.append(f"LIBRARY = {library}")
    lines += [f"RETAINED = {retained}", "LINE_COMMENTS = 1", ""]
    if setup.tools_file is not None:
        # LinuxCNC's own tool table key, which the plug-in reads when [NCKIT] names none.
        lines += ["[EMCIO]", f"TOOL_TABLE = {setup.tools_file}", ""]
    path.write_text("\n".join(lines))


def run_plugin(args, program: Path, setup: cl.Setup, library: Path | None, work: Path) -> str:
    """rs274's canonical calls with the plug-in (AssertionError: not loaded or failed)."""
    ini = work / "plugin.ini"
    write_ini(ini, setup, library, work / "plugin.vars")
    cmd = [args.rs274, "-p", str(args.plugin), "-i", str(ini),
           *(["-b"] if setup.block_delete else []), "-g", str(program)]
    proc = subprocess.run(cmd, cwd=work, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=args.timeout)
    loaded = f"{CUSTOM} '{args.plugin}'"
    if loaded not in proc.stderr:
        raise AssertionError(f"rs274 did not use the plug-in (no \"{loaded}\"): "
                             f"{' | '.join(proc.stderr.strip().splitlines()[:3])}")
    if proc.returncode != 0:
        msg = [l for l in proc.stderr.splitlines()
               if l.strip() and l.strip() != "executing" and CUSTOM not in l]
        raise AssertionError(f"rs274 -p exit status {proc.returncode}: {' | '.join(msg)}")
    return proc.stdout


def compare_one(args, program: Path, library: Path | None) -> tuple[bool, str]:
    with tempfile.TemporaryDirectory(prefix="nckit-plugin-") as tmp:
        work = Path(tmp)
        try:
            setup = cl.setup_of(program, args.machines)
            machine = cl.load_machine(setup.machine_file) if setup.machine_file else cl.DEFAULT_MILL
            out = run_plugin(args, program, setup, library, work)
            # The plug-in hands LinuxCNC radii on a diameter-mode lathe (canon has no G7).
            ref = cl.parse_rs274(out, machine["diameter_mode"], radius_program=True)
            extra = ["--vars", str(work / "nckit.vars")]
            if library is not None:
                extra += ["--library", str(library)]
            records = cl.run_nckit(args.nckit, program, setup, work, args.timeout, extra)
            got = [cl.nckit_motion(r, i) for i, r in enumerate(records, start=1)
                   if r["kind"] in cl.COMPARED_KINDS]
        except (AssertionError, cl.ProgramError) as e:
            return False, f"FAIL {program.name}: {e}"
        except subprocess.TimeoutExpired:
            return False, f"FAIL {program.name}: timed out"
        if not ref:
            return False, f"FAIL {program.name}: the plug-in issued no motion"
        axes = set(machine["axes"]) or (set(got[0].end) if got else {"X", "Y", "Z"})
        src = program.read_text(encoding="utf-8", errors="replace").splitlines()
        diff = cl.compare(ref, got, axes, src, check_lines=True, check_feed=True)
        if diff:
            return False, f"FAIL {program.name}: {diff}"
        return True, f"ok {program.name} ({len(ref)} motions)"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", type=Path, required=True, help="libnckit_linuxcnc.so")
    ap.add_argument("--nckit", required=True, help="nckit binary")
    ap.add_argument("--rs274", default=None, help="LinuxCNC rs274 (default: from PATH)")
    ap.add_argument("--programs", type=Path, action="append", required=True,
                    help="folder of NN_name.ngc / NN_name.nc programs (repeatable); called "
                         "programs come from its library/ folder when there is one")
    ap.add_argument("--machines", type=Path, default=cl.DEFAULT_MACHINES)
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds per run")
    ap.add_argument("names", nargs="*", help="only these programs (file name or stem)")
    args = ap.parse_args()

    args.rs274 = args.rs274 or shutil.which("rs274")
    if not args.rs274:
        print("error: LinuxCNC's rs274 not found; run scripts/deps.sh", file=sys.stderr)
        return 1
    args.plugin = args.plugin.resolve()  # rs274 -p looks a relative name up in LinuxCNC's lib
    if not args.plugin.is_file():
        print(f"error: plug-in {args.plugin} not built", file=sys.stderr)
        return 1
    args.nckit = str(Path(args.nckit).resolve())
    args.machines = args.machines.resolve()

    results = []
    for folder in args.programs:
        folder = folder.resolve()
        library = folder / "library" if (folder / "library").is_dir() else None
        programs = sorted(p for p in folder.iterdir()
                          if p.suffix in (".ngc", ".nc") and p.name[:2].isdigit())
        for program in programs:
            if args.names and program.name not in args.names and program.stem not in args.names:
                continue
            ok, text = compare_one(args, program, library)
            print(text, flush=True)
            results.append(ok)
    if not results:
        print("error: no programs compared", file=sys.stderr)
        return 1
    failed = results.count(False)
    print(f"{len(results) - failed} of {len(results)} programs match")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
