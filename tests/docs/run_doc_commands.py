#!/usr/bin/env python3
"""Runs every shell command written in README.md, CONTRIBUTING.md and docs/**/*.md.

A command is a line of a fenced block whose info string is `sh`, `bash` or `shell` (lines
joined at a trailing backslash or until a loop or quote is complete, comment lines left out), or
a `$ ` line of a `console` block.
An HTML comment on the line just before the fence changes how the block is run:

    <!-- doc-test: skip REASON -->   not run (LinuxCNC, root, a browser, minutes of work);
                                     listed as skipped with REASON
    <!-- doc-test: exit N -->        every command of the block must exit with status N

Every other command must exit 0 within --timeout seconds. Commands run one by one, in the order
of the page, with bash, in a scratch folder that links the source tree's top-level entries (so
`examples/...` and `tests/...` resolve), with `build/release/src/nckit` and `nckit` on the PATH
being the binary under test; `/tmp/` in a command is replaced by the scratch folder's `tmp/`, so
outputs never land in the shared /tmp. Exit status 0 when every command passed, 1 otherwise
(or when no command was found at all).
"""
import argparse
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

SHELL_FENCES = {"sh", "bash", "shell"}
MARKER = re.compile(r"^\s*<!--\s*doc-test:\s*(skip|exit)\b\s*(.*?)\s*-->\s*$")
# What can leave a command open at the end of a line: a compound command, a here-document, a
# quote, a group, a pipe or && / || waiting for their right side.
MAY_OPEN = re.compile(r"\b(for|while|until|if|case|select|function)\b|<<|[{(\"'`]|(\||&&)\s*$")
FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([A-Za-z0-9_+-]*)")


@dataclass
class Block:
    page: str
    line: int
    commands: list = field(default_factory=list)  # (line, text)
    skip_reason: str | None = None
    expected_exit: int = 0


def complete(command: str) -> bool:
    """Whether bash reads `command` as whole (a `for ... do` without its `done` is not, nor a
    here-document without its end marker, which bash only warns about)."""
    if not MAY_OPEN.search(command):
        return True  # nothing that can span lines: spare the bash start-up
    checked = subprocess.run(["bash", "-n", "-c", command], stdin=subprocess.DEVNULL,
                             capture_output=True)
    return checked.returncode == 0 and b"here-document" not in checked.stderr


def join_continuations(lines):
    """(line number, text) pairs joined into whole commands: at a trailing backslash, and until
    a multi-line construct (a loop, an if, a quote) is complete; comment lines are left out."""
    out, pending, start = [], "", 0
    for number, text in lines:
        if not pending:
            if not text.strip() or text.lstrip().startswith("#"):
                continue
            start = number
        stripped = text.rstrip()
        if stripped.endswith("\\"):
            pending += stripped[:-1] + " "
            continue
        pending += text
        if complete(pending):
            out.append((start, pending.strip()))
            pending = ""
        else:
            pending += "\n"
    if pending.strip():
        out.append((start, pending.strip()))
    return out


def parse_page(path: Path, name: str):
    """The shell blocks of one page, and any marker that is not followed by a fence."""
    blocks, problems = [], []
    lines = path.read_text(encoding="utf-8").splitlines()
    i = 0
    marker = None  # (kind, argument, line) of the marker just above
    while i < len(lines):
        text = lines[i]
        m = MARKER.match(text)
        if m:
            if marker:
                problems.append(f"{name}:{marker[2]}: doc-test marker not followed by a fence")
            marker = (m.group(1), m.group(2), i + 1)
            i += 1
            continue
        fence = FENCE.match(text)
        if not fence:
            if marker and text.strip():
                problems.append(f"{name}:{marker[2]}: doc-test marker not followed by a fence")
                marker = None
            i += 1
            continue
        ticks, language = fence.group(2), fence.group(3).lower()
        body, j = [], i + 1
        while j < len(lines) and not lines[j].lstrip().startswith(ticks):
            body.append((j + 1, lines[j]))
            j += 1
        if language in SHELL_FENCES or language == "console":
            block = Block(name, i + 1)
            if language == "console":
                block.commands = join_continuations(
                    [(n, t.lstrip()[2:]) for n, t in body if t.lstrip().startswith("$ ")])
            else:
                block.commands = join_continuations(body)
            if marker and marker[0] == "skip":
                block.skip_reason = marker[1] or "no reason given"
                if not marker[1]:
                    problems.append(f"{name}:{marker[2]}: doc-test: skip needs a reason")
            elif marker and marker[0] == "exit":
                try:
                    block.expected_exit = int(marker[1])
                except ValueError:
                    problems.append(f"{name}:{marker[2]}: doc-test: exit needs a number")
            if block.commands:
                blocks.append(block)
        elif marker:
            problems.append(f"{name}:{marker[2]}: doc-test marker above a '{language}' block")
        marker = None
        i = j + 1
    if marker:
        problems.append(f"{name}:{marker[2]}: doc-test marker not followed by a fence")
    return blocks, problems


def pages(source: Path):
    found = [source / "README.md", source / "CONTRIBUTING.md"]
    found += sorted((source / "docs").rglob("*.md"))
    return [p for p in found if p.is_file()]


def make_scratch(source: Path, nckit: Path, root: Path) -> Path:
    """A folder that looks like the source tree with the binary under test at its usual place."""
    work = root / "work"
    work.mkdir()
    for entry in source.iterdir():
        if entry.name not in ("build", ".git"):
            (work / entry.name).symlink_to(entry)
    (work / "build" / "release" / "src").mkdir(parents=True)
    (work / "build" / "release" / "src" / "nckit").symlink_to(nckit)
    (root / "bin").mkdir()
    (root / "bin" / "nckit").symlink_to(nckit)
    (root / "tmp").mkdir()
    return work


def run_command(command: str, work: Path, env: dict, timeout_s: float):
    """(exit status or None on timeout, output). The command runs in its own process group,
    which is killed whole on timeout, so nothing it started outlives it."""
    process = subprocess.Popen(["bash", "-c", command], cwd=work, env=env,
                               stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout_s)
        return process.returncode, output
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        output, _ = process.communicate()
        return None, output


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nckit", required=True, type=Path, help="the nckit binary under test")
    parser.add_argument("--source", type=Path, default=Path(__file__).resolve().parents[2],
                        help="the source tree (default: this script's)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds per command")
    parser.add_argument("--list", action="store_true", help="list the commands, run nothing")
    args = parser.parse_args()
    source = args.source.resolve()
    nckit = args.nckit.resolve()

    blocks, problems = [], []
    for path in pages(source):
        found, wrong = parse_page(path, str(path.relative_to(source)))
        blocks += found
        problems += wrong
    for problem in problems:
        print(f"MARKER {problem}")
    commands = sum(len(b.commands) for b in blocks)
    if commands == 0:
        print("no commands found in the documentation")
        return 1

    failures, ran, skipped = len(problems), 0, 0
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="nckit-docs-") as scratch:
        root = Path(scratch)
        work = make_scratch(source, nckit, root)
        env = dict(os.environ)
        env["PATH"] = f"{root / 'bin'}{os.pathsep}{env.get('PATH', '')}"
        for block in blocks:
            for line, command in block.commands:
                where = f"{block.page}:{line}"
                if block.skip_reason is not None:
                    skipped += 1
                    print(f"SKIP {where}: {command}\n     ({block.skip_reason})")
                    continue
                if args.list:
                    print(f"RUN  {where}: {command}")
                    continue
                runnable = command.replace("/tmp/", f"{root / 'tmp'}/")
                t0 = time.monotonic()
                status, output = run_command(runnable, work, env, args.timeout)
                seconds = time.monotonic() - t0
                ran += 1
                if status == block.expected_exit:
                    print(f"ok   {where} ({seconds:.2f} s): {command}")
                    continue
                failures += 1
                said = "timed out" if status is None else f"exit {status}, wanted {block.expected_exit}"
                print(f"FAIL {where} ({said}): {command}")
                tail = output.decode(errors="replace").splitlines()[-15:]
                for text in tail:
                    print(f"     | {text}")
    total = time.monotonic() - started
    print(f"{ran} commands run, {skipped} skipped, {failures} failed, {total:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
