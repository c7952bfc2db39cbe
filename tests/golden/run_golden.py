#!/usr/bin/env python3
"""Golden tests for `nckit moves`: each NAME.ngc beside NAME.moves (expected stdout) and, for a
program that must be refused, NAME.err (expected stderr; exit status 2 and no stdout after the
error). The first lines may name the machine: `( nckit-machine: lathe.toml )`, resolved in
tests/golden/machines/ or examples/machines/; `( nckit-json )` there asks for JSON lines. `--update` rewrites the expected files from the current output."""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
MACHINE_RE = re.compile(r"nckit-machine:\s*([\w.\-/]+)")


def extra_args(program: pathlib.Path) -> list[str]:
    first = " ".join(program.read_text().splitlines()[:3])  # directives sit in the first lines
    args = ["--json"] if "nckit-json" in first else []
    match = MACHINE_RE.search(first)
    if match:
        local = program.parent / "machines" / match.group(1)
        args += ["--machine", str(local if local.exists() else ROOT / "examples" / "machines" / match.group(1))]
    return args


def run(nckit: str, program: pathlib.Path) -> subprocess.CompletedProcess:
    # Run from the program's folder with a relative path so messages do not depend on the checkout.
    return subprocess.run([nckit, "moves", program.name, *extra_args(program)], cwd=program.parent,
                          capture_output=True, text=True, timeout=60)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--nckit", required=True)
    parser.add_argument("--update", action="store_true")
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()
    args.nckit = str(pathlib.Path(args.nckit).resolve())
    folder = pathlib.Path(__file__).resolve().parent
    programs = sorted(folder.glob("*.ngc"))
    if args.names:
        programs = [p for p in programs if p.stem in args.names]
    passed = failed = 0
    for program in programs:
        result = run(args.nckit, program)
        moves_file = program.with_suffix(".moves")
        err_file = program.with_suffix(".err")
        if args.update:
            moves_file.write_text(result.stdout)
            if result.returncode != 0:
                err_file.write_text(result.stderr)
            elif err_file.exists():
                err_file.unlink()
            print(f"updated {program.name}")
            continue
        expected_status = 2 if err_file.exists() else 0
        problems = []
        if result.returncode != expected_status:
            problems.append(f"exit status {result.returncode}, expected {expected_status}: {result.stderr.strip()}")
        if not moves_file.exists():
            problems.append(f"{moves_file.name} is missing")
        elif result.stdout != moves_file.read_text():
            want = moves_file.read_text().splitlines()
            got = result.stdout.splitlines()
            for i, (w, g) in enumerate(zip(want + [""] * len(got), got + [""] * len(want))):
                if w != g:
                    problems.append(f"stdout line {i + 1}: expected '{w}', got '{g}'")
                    break
        if err_file.exists() and result.stderr != err_file.read_text():
            problems.append(f"stderr: expected '{err_file.read_text().strip()}', got '{result.stderr.strip()}'")
        if problems:
            failed += 1
            print(f"FAIL {program.name}: " + "; ".join(problems))
        else:
            passed += 1
            print(f"ok {program.name}")
    if not args.update:
        print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
