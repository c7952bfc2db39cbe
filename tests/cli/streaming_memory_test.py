#!/usr/bin/env python3
"""A 10,000,000-line program through `nckit moves`, fed through a pipe so that neither side
holds it: every move comes out, and nckit's peak memory stays that of a short program."""
import tempfile
import subprocess
import sys

LINES = 10_000_000
PEAK_LIMIT_MB = 12  # a short program takes about 5 MB; holding 10M moves would take gigabytes


def main() -> int:
    nckit = sys.argv[1]
    # GNU time reports nckit's own peak; a child's rusage seen from here would include the copy
    # of this Python process it was forked from.
    usage_file = tempfile.NamedTemporaryFile(mode="r", suffix=".rss")
    process = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", usage_file.name,
                                nckit, "moves", "/dev/stdin"], stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    counter = subprocess.Popen(["wc", "-l"], stdin=process.stdout, stdout=subprocess.PIPE, text=True)
    process.stdout.close()
    chunk = []
    process.stdin.write(b"G21 G90 G94 F3000\n")
    for i in range(LINES):
        chunk.append(b"G1 X%d.%03d Y%d\n" % (i % 200 - 100, i % 1000, (i // 200) % 100))
        if len(chunk) == 100_000:
            process.stdin.write(b"".join(chunk))
            chunk.clear()
    process.stdin.write(b"".join(chunk) + b"M30\n")
    process.stdin.close()
    stderr = process.stderr.read().decode()
    status = process.wait()
    printed = int(counter.communicate()[0].strip())
    peak_mb = int(usage_file.read().split()[-1]) / 1024.0
    print(f"exit {status}, {printed} lines printed, peak memory {peak_mb:.1f} MB {stderr.strip()}")
    ok = status == 0 and printed == LINES + 1 and peak_mb < PEAK_LIMIT_MB
    print(f"{1 if ok else 0} passed, {0 if ok else 1} failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
