#!/usr/bin/env python3
"""The `nckit steps` contract: binary records = text lines, counts end at round(position × spu),
the compressed form reproduces every step within the bound, bad programs write nothing (exit 2)."""
import pathlib
import struct
import subprocess
import sys
import tempfile

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAIL {what}")


def steps(nckit, *args):
    return subprocess.run([nckit, "steps", *map(str, args)], capture_output=True, timeout=120)


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        program = tmp / "p.ngc"
        # 800 steps/mm on the built-in mill: X ends at 12.3456 mm → 9876 steps, Y at -1 → -800.
        program.write_text("G21 G90 G17\nG1 X10 Y5 F3000\nG2 X20 Y5 I5 J0\nG1 X12.3456 Y-1\nG0 Z0\nM30\n")
        text = steps(nckit, program, "--text")
        check(text.returncode == 0, f"--text exits 0 ({text.stderr})")
        lines = [tuple(int(v) for v in line.split()) for line in text.stdout.decode().splitlines()]
        out = tmp / "s.bin"
        binary = steps(nckit, program, "-o", out)
        check(binary.returncode == 0, "binary exits 0")
        data = out.read_bytes()
        check(len(data) == 10 * len(lines), "10-byte records, one per text line")
        records = [struct.unpack_from("<qBb", data, 10 * k) for k in range(len(data) // 10)]
        check(records == lines, "binary records equal the text lines")
        check(all(a[0] <= b[0] for a, b in zip(lines, lines[1:])), "events in time order")
        counts = [0, 0, 0]
        for _, axis, direction in lines:
            counts[axis] += direction
        check(counts == [9876, -800, 0], f"final counts {counts}")

        for bound_us in (25, 2):
            queued = tmp / "q.txt"
            run = steps(nckit, program, "--compress", bound_us, "-o", queued)
            check(run.returncode == 0 and b"compression ratio" in run.stderr, "--compress reports its ratio")
            direction = {}
            t_prev = {}
            made = {0: [], 1: [], 2: []}
            for line in queued.read_text().splitlines():
                words = line.split()
                axis = int(words[1])
                if words[0] == "set_next_step_dir":
                    direction[axis] = int(words[2])
                    continue
                interval, count, add = map(int, words[2:])
                t = t_prev.get(axis, 0)
                for _ in range(count):
                    t += interval
                    interval += add
                    made[axis].append((t, direction[axis]))
                t_prev[axis] = t
            for axis in range(3):
                exact = [(t, d) for t, a, d in lines if a == axis]
                check(len(exact) == len(made[axis]), f"axis {axis}: every step reproduced")
                worst = max((abs(m[0] - e[0]) for m, e in zip(made[axis], exact)), default=0)
                check(worst <= bound_us * 1000, f"axis {axis}: worst error {worst} ns within {bound_us} us")
                check(all(m[1] == e[1] for m, e in zip(made[axis], exact)), f"axis {axis}: directions")

        bad = tmp / "bad.ngc"
        bad.write_text("G1 X10 F100\nG1 X20 Q5\n")
        target = tmp / "bad.bin"
        run = steps(nckit, bad, "-o", target)
        check(run.returncode == 2, "a bad program exits 2")
        check(not target.exists() and not (tmp / "bad.bin.partial").exists(), "a bad program writes nothing")
    print(f"{'FAILED' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
