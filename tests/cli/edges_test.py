#!/usr/bin/env python3
"""Errors a user can act on and streaming, seen from outside: check reports every error at once,
no exit 0 having done nothing, hints, byte-order marks, standard input, bounded runaways, and
`steps --text | head -1` on a 2,000,000-line program in bounded memory."""
import pathlib
import subprocess
import sys
import tempfile

from cli_checks import check, run_nckit, summary

ROOT = pathlib.Path(__file__).resolve().parents[2]
MACHINES = ROOT / "examples" / "machines"


def run(nckit, *args, stdin=None, timeout=120):
    return run_nckit(nckit, *args, text=True, input=stdin, timeout=timeout)


def streaming_steps(nckit, tmp) -> None:
    """2,000,000 lines into `steps - --text | head -1`: nckit must not hold the step stream."""
    usage = tmp / "steps.rss"
    process = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", str(usage), nckit, "steps", "-", "--text"],
                               stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    head = subprocess.Popen(["head", "-1"], stdin=process.stdout, stdout=subprocess.PIPE, text=True)
    process.stdout.close()
    try:
        process.stdin.write(b"G21 G90 G94 F6000\n")
        chunk = []
        for i in range(2_000_000):
            chunk.append(b"G1 X%d Y%d\n" % (i % 200 - 100, (i // 200) % 100))
            if len(chunk) == 100_000:
                process.stdin.write(b"".join(chunk))
                chunk.clear()
        process.stdin.write(b"".join(chunk) + b"M30\n")
        process.stdin.close()
    except BrokenPipeError:
        pass  # nckit stopped reading once head had its line: what streaming allows
    first = head.communicate(timeout=300)[0]
    process.wait(timeout=300)
    peak_mb = int(usage.read_text().split()[-1]) / 1024.0
    print(f"steps - --text | head -1 on 2,000,000 lines: peak memory {peak_mb:.1f} MB")
    check(len(first.split()) == 3, f"head gets a step line ({first!r})")
    check(peak_mb < 64, f"steps streams to stdout (peak {peak_mb:.1f} MB)")


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = pathlib.Path(tmp_name)

        def program(name, text, mode="w"):
            path = tmp / name
            if isinstance(text, bytes):
                path.write_bytes(text)
            else:
                path.write_text(text)
            return path

        # check: every error in one pass, in order, exit 2.
        four = program("four.ngc", "G1 X10 F100\nG1 Q5\nG1 X20\nG5 X1\nG1 X9999\nG1 X1 Y1 I4\nM30\n")
        r = run(nckit, "check", four)
        errors = [l for l in r.stderr.splitlines() if ": error: " in l]
        check(r.returncode == 2 and [e.split(":")[1] for e in errors] == ["2", "4", "5", "6"],
              f"check reports all four errors ({r.stderr.strip()})")
        r = run(nckit, "check", four, "--max-errors", "2")
        check(len([l for l in r.stderr.splitlines() if ": error: " in l]) == 2 and "--max-errors" in r.stderr,
              "check stops at --max-errors")
        check(run(nckit, "check", ROOT / "examples" / "01_mill_pocket.ngc").returncode == 0, "a clean program checks 0")

        # Comments nest as Haas's example programs write them; one left open is an error where it opens.
        nested = program("nested.nc", "G21 G90 G1 F100 (T2 #10 drill (for the .194 hole))\nX1 ((a) b)\nM30\n")
        r = run(nckit, "moves", nested)
        check(r.returncode == 0 and r.stdout.startswith("G1 X1.0000 Y0.0000"), f"nested comments are comments ({r.stderr.strip()})")
        unclosed = program("unclosed.nc", "G21 G90 G1 F100\nX1 (a (b c)\nX2\nM30\n")
        r = run(nckit, "moves", unclosed)
        check(r.returncode == 2 and r.stdout == "" and f"{unclosed}:2:4: error: comment is not closed" in r.stderr,
              f"an unclosed comment is an error at its '(' ({r.stderr.strip()})")
        inner = program("inner.nc", "G21 G90 G1 F100\nX1 (a (b (c) d\nM30\n")
        r = run(nckit, "check", inner)
        check(r.returncode == 2 and f"{inner}:2:7: error: comment is not closed: the '(' here, inside the comment "
              "opened at column 4" in r.stderr, f"an inner '(' left open is the error, where it opens ({r.stderr.strip()})")

        # Nothing done is no success.
        empty = program("empty.ngc", "\n\n")
        r = run(nckit, "moves", empty)
        check(r.returncode == 2 and "empty" in r.stderr, f"an empty program is an error ({r.stderr.strip()})")
        r = run(nckit, "notch", ROOT / "examples" / "notch" / "conrod.nc")
        check(r.returncode == 2 and "laser_on_mcodes" in r.stderr, f"notch without laser codes ({r.stderr.strip()})")
        r = run(nckit, "crosshatch", ROOT / "examples" / "crosshatch" / "bore_12heads_30deg.toml", "--text")
        check(r.returncode == 2 and "--steps" in r.stderr, "crosshatch --text needs --steps")
        r = run(nckit, "moves", ROOT / "examples" / "01_mill_pocket.ngc", "--json", "--summary")
        check(r.returncode == 2, "moves --json --summary is refused")

        # Hints.
        r = run(nckit, "plna", "x.ngc")
        check(r.returncode == 2 and "did you mean 'plan'" in r.stderr and "moves" in r.stderr,
              f"unknown verb hint ({r.stderr.strip()})")
        r = run(nckit, "moves", MACHINES / "mill.toml")
        check(r.returncode == 2 and "TOML" in r.stderr and "--machine" in r.stderr, "a TOML file as program")
        r = run(nckit, "moves", program("call.nc", "M98 P1234\nM30\n"))
        check(r.returncode == 2 and "alarm 78" in r.stderr and "--library" in r.stderr and "looked in" in r.stderr,
              f"alarm 78 says where it looked ({r.stderr.strip()})")
        r = run(nckit, "moves", program("dwell.nc", "G4 P1.5\nM30\n"))
        check(r.returncode == 0 and "warning" in r.stderr and "X1.5" in r.stderr, f"G4 P1.5 warns ({r.stderr.strip()})")
        # A 0.092 in bore read as mm: an arc under 0.2 mm across warns, once; in G20 it does not.
        bore = "G21 G90 G0 X10 Y10 Z1\nG1 Z-1 F100\nG2 X10.046 Y10 I0.023 J0 F50\nG2 X10 Y10 I-0.023 J0\nM30\n"
        r = run(nckit, "check", program("bore.nc", bore))
        check(r.returncode == 0 and r.stderr.count("implausibly small") == 1 and "bore.nc:3:" in r.stderr
              and "G20" in r.stderr, f"a 0.046 mm arc warns once ({r.stderr.strip()})")
        r = run(nckit, "check", program("bore_inch.nc", bore.replace("G21", "G20").replace("Z-1", "Z-0.04")
                                        .replace("Z1", "Z0.04").replace("X10", "X1").replace("Y10", "Y1")))
        check(r.returncode == 0 and "implausibly" not in r.stderr, f"an inch bore does not warn ({r.stderr.strip()})")
        r = run(nckit, "moves", ROOT / "examples" / "02_lathe_shaft.ngc")
        check(r.returncode == 2 and "--machine" in r.stderr, f"a lathe program on the mill hints ({r.stderr.strip()})")

        # Byte-order marks and standard input.
        bom = program("bom.ngc", b"\xef\xbb\xbfG1 X1 F100\nM30\n")
        r = run(nckit, "moves", bom)
        check(r.returncode == 0 and r.stdout.startswith("G1 X1.0000"), f"a BOM program runs ({r.stderr.strip()})")
        machine = program("bom.toml", b"\xef\xbb\xbf" + (MACHINES / "mill.toml").read_bytes())
        r = run(nckit, "moves", bom, "--machine", machine)
        check(r.returncode == 0, f"a BOM machine file loads ({r.stderr.strip()})")
        text = (ROOT / "examples" / "01_mill_pocket.ngc").read_text()
        for verb in ("moves", "check", "expand", "plan", "steps"):
            r = subprocess.run([nckit, verb, "-"], input=text.encode(), capture_output=True, timeout=120)
            check(r.returncode == 0, f"{verb} - reads standard input ({r.stderr.decode().strip()})")

        # Fuzz findings: numbers out of range are errors, not undefined behaviour.
        r = run(nckit, "moves", program("o.nc", "O99999999999999999999\nG1 X1 F100\nM30\n"))
        check(r.returncode == 2 and "0-99999999" in r.stderr, f"a huge O number is refused ({r.stderr.strip()})")
        r = run(nckit, "moves", program("n.nc", "N99999999999999999999 G1 X1 F100\nM30\n"))
        check(r.returncode == 2, "a huge N number is refused")
        r = run(nckit, "moves", program("var.nc", "#1 = #99999999999999999999\nM30\n"))
        check(r.returncode == 2 and "alarm 115" in r.stderr, f"#<huge literal> is alarm 115 ({r.stderr.strip()})")
        # Two GOTOs across 10,000 empty lines: the search counts against the runaway budget.
        runaway = program("runaway.nc", "N1 GOTO2\n" + "\n" * 10000 + "N2 GOTO1\n")
        r = run(nckit, "moves", runaway, "--max-blocks", "1000000", timeout=60)
        check(r.returncode == 2 and "alarm 100" in r.stderr, f"GOTO ping-pong stops at alarm 100 ({r.stderr.strip()})")
        bad_machine = program("tiny.toml", (MACHINES / "mill.toml").read_text().replace(
            "max_velocity = 100.0", "max_velocity = 1e-308", 1))
        r = run(nckit, "plan", ROOT / "examples" / "01_mill_pocket.ngc", "--machine", bad_machine, "--json")
        check(r.returncode == 2 and "implausible" in r.stderr and "inf" not in r.stdout,
              f"max_velocity = 1e-308 is refused ({r.stderr.strip()})")

        streaming_steps(nckit, tmp)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
