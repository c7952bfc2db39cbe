#!/usr/bin/env python3
"""The `nckit steps` contract: binary records = text lines, counts end at round(position × spu),
the compressed form reproduces every step within the bound, bad programs write nothing (exit 2);
on phase-table axes --text adds the port byte after each step."""
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


ROOT = pathlib.Path(__file__).resolve().parents[2]
STEPPER_MILL = ROOT / "examples" / "machines" / "stepper_mill.toml"
# The seed's port codes for the six beats A AB B BC C CA (docs/drives.md).
SEED_CODES = [0x0B, 0x09, 0x0D, 0x0C, 0x0E, 0x0A]
# 2-phase half step, winding A the highest of four bits: A AB B BC C CD D DA.
TWO_PHASE_HALF = [0b1000, 0b1100, 0b0100, 0b0110, 0b0010, 0b0011, 0b0001, 0b1001]


def check_ports(nckit, tmp, program, machine, codes, what):
    """Every --text line of a phase-table machine ends in the byte of the motor's count mod the
    table (backlash steps included); the binary records are the same steps without it."""
    text = steps(nckit, program, "--machine", machine, "--text")
    check(text.returncode == 0, f"{what}: --text exits 0 ({text.stderr})")
    rows = [line.split() for line in text.stdout.decode().splitlines()]
    check(len(rows) > 100 and all(len(r) == 4 for r in rows), f"{what}: four columns on every line")
    motor = [0, 0, 0]  # the program starts at X0 Y0 Z0: beat 0
    bad = 0
    for t, axis, direction, port in rows:
        axis = int(axis)
        motor[axis] += int(direction)
        bad += port != f"0x{codes[motor[axis] % len(codes)]:02X}"
    check(bad == 0, f"{what}: {bad} port bytes differ from the table at the motor's count")
    first_x = [r[3] for r in rows if r[1] == "0"][:6]
    check(first_x == [f"0x{c:02X}" for c in codes[1:] + codes[:1]][:6], f"{what}: first X bytes {first_x}")
    out = tmp / "ports.bin"
    binary = steps(nckit, program, "--machine", machine, "-o", out)
    data = out.read_bytes() if binary.returncode == 0 else b""
    records = [struct.unpack_from("<qBb", data, 10 * k) for k in range(len(data) // 10)]
    check(records == [(int(r[0]), int(r[1]), int(r[2])) for r in rows], f"{what}: binary records unchanged")
    return motor


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

        # Phase tables: the retrofit mill's seed codes, with reversals (and backlash) and an arc.
        stepper = tmp / "stepper.ngc"
        stepper.write_text("G21 G90 G17\nG1 X3 Y-2 F600\nG1 X1.23\nG2 X5.23 Y-2 I2 J0\nG1 Z-1.5\n"
                           "G1 X-0.07 Y0.41 Z0.2\nM30\n")
        motor = check_ports(nckit, tmp, stepper, STEPPER_MILL, SEED_CODES, "3phase-6beat seed port")
        # Motor = commanded count + 2 backlash steps in the direction of each reversal: X reverses
        # - + - (ends at -7 - 2), Y + - + (41 + 2), Z has no backlash (20).
        check(motor == [-9, 43, 20], f"motor counts {motor}")
        two_phase = tmp / "two_phase.toml"
        two_phase.write_text(STEPPER_MILL.read_text()
                             .replace('"3phase-6beat"', '"2phase-half"')
                             .replace("port_active_low = true", "port_active_low = false")
                             .replace("port_set_bits = 0x08", "port_set_bits = 0x80"))
        check_ports(nckit, tmp, stepper, two_phase, [0x80 | b for b in TWO_PHASE_HALF], "2phase-half, enable bit")

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
