#!/usr/bin/env python3
"""The progress line of a long run (docs/cli-safety.md, Progress), seen as a user sees it: nckit
with its stderr on a pseudo-terminal. A run of a few seconds draws "nckit steps: N blocks, R
blocks/s, P %, T s left" in place (carriage return, clear to end of line), with counts and shares
that grow, and clears it at the end; with --quiet, or with stderr not a terminal, stderr stays
empty. Usage: progress_test.py NCKIT"""
import os
import pty
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from cli_checks import check, summary

REPORT_LINE = re.compile(r"nckit report: ([\d,]+) blocks, ([\d,]+) blocks/s, (\d+) %, (\d+) s left\x1b\[K")
LINE = re.compile(r"nckit steps: ([\d,]+) blocks, ([\d,]+) blocks/s, (\d+) %, (\d+) s left\x1b\[K")


def long_program(folder: Path, blocks: int = 150_000) -> Path:
    """Back and forth along X: enough blocks that `steps` runs for several seconds."""
    path = folder / f"long_{blocks}.nc"
    with path.open("w") as out:
        out.write("G21 G90 G64 P0.01 F6000\n")
        for i in range(blocks):
            out.write(f"G1 X{(i % 50) * 0.2:.1f} Y{(i % 7) * 0.1:.1f}\n")
        out.write("M30\n")
    return path


def stderr_on_terminal(nckit, *args):
    """Runs nckit with stdout to /dev/null and stderr on a pseudo-terminal; returns (status,
    everything written to the terminal)."""
    leader, follower = pty.openpty()
    with open(os.devnull, "wb") as null:
        process = subprocess.Popen([nckit, *map(str, args)], stdout=null, stderr=follower, stdin=subprocess.DEVNULL)
    os.close(follower)
    seen = b""
    while True:
        try:
            chunk = os.read(leader, 4096)
        except OSError:  # the terminal closes when nckit exits
            break
        if not chunk:
            break
        seen += chunk
    os.close(leader)
    return process.wait(timeout=300), seen.decode("utf-8", "replace")


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        program = long_program(Path(tmp))
        status, seen = stderr_on_terminal(nckit, "steps", program, "--text")
        check(status == 0, f"steps ran ({status}: {seen[-300:]!r})")
        lines = LINE.findall(seen)
        check(len(lines) >= 2, f"the progress line is drawn and redrawn ({len(lines)} times: {seen[:300]!r})")
        if lines:
            counts = [int(c.replace(",", "")) for c, _, _, _ in lines]
            shares = [int(p) for _, _, p, _ in lines]
            check(counts == sorted(counts) and counts[0] > 0, f"block counts grow ({counts})")
            check(shares == sorted(shares) and 0 <= shares[0] and shares[-1] <= 100, f"shares grow within 0-100 % ({shares})")
            check(all(int(r.replace(",", "")) > 0 for _, r, _, _ in lines), "the rate is positive")
        check("\r" in seen and seen.rstrip("\r\n").endswith("\r\x1b[K"), f"the line is redrawn in place and cleared at the end ({seen[-40:]!r})")
        status, seen = stderr_on_terminal(nckit, "steps", program, "--text", "--quiet")
        check(status == 0 and seen.strip() == "", f"--quiet: nothing on the terminal ({seen[:200]!r})")
        plain = subprocess.run([nckit, "steps", str(program), "--text"], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, timeout=300)
        check(plain.returncode == 0 and plain.stderr == b"", f"stderr not a terminal: silent ({plain.stderr[:200]!r})")
        # nckit report draws the same line while it plans, and --quiet silences it. Its planning
        # is faster than `steps`: 150,000 blocks plan in under a second on a quiet machine, before
        # the line's first draw, so the report gets three times as many.
        program = long_program(Path(tmp), 450_000)
        page = Path(tmp) / "long.html"
        status, seen = stderr_on_terminal(nckit, "report", program, "-o", page)
        report_lines = REPORT_LINE.findall(seen)
        check(status == 0 and page.is_file(), f"report wrote its page ({status}: {seen[-300:]!r})")
        check(len(report_lines) >= 1 and seen.rstrip("\r\n").endswith("\r\x1b[K"),
              f"report: the progress line is drawn and cleared ({len(report_lines)} times: {seen[:200]!r})")
        status, seen = stderr_on_terminal(nckit, "report", program, "-o", page, "--quiet")
        check(status == 0 and seen.strip() == "", f"report --quiet: nothing on the terminal ({seen[:200]!r})")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
