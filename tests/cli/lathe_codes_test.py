#!/usr/bin/env python3
"""Fanuc's three lathe G-code systems and every lathe code's malformed use, as a user runs them.

1. One part written in system A (single cycles G90/G94/G92, G71-G76, G50 S clamp, G98/G99) and
   the same part with each code renamed by Fanuc's table (docs/gcode-lathe.md, "The three
   systems") for system B and for system C make the same `nckit moves --json` records, on the
   example lathe and on its system-B and system-C twins (machine files written here from
   examples/machines/lathe.toml). The records are compared whole except the source line.
2. One malformed use of each lathe code through `nckit plan`: FILE:LINE:COL: error: at the
   offending word and exit status 2, nothing printed on stdout. (lathe_cli_test.py has the
   cases of G90, G91/G95 in system A, a wrong-sign G71, G10 P200 and the one-block forms.)"""
import json
import pathlib
import re
import sys
import tempfile

from cli_checks import check, run_nckit, summary

ROOT = pathlib.Path(__file__).resolve().parents[2]
LATHE = ROOT / "examples" / "machines" / "lathe.toml"

# The part in system A: every cycle of the table once, from one start point each.
PART_A = """G50 S2000
G96 S150 M3
G0 X60. Z2.
G90 X50. Z-30. F0.25
X45.
G94 X20. Z-2. F0.2
G0 X60. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G0 X30.
G1 Z-10. F0.1
X40. Z-20.
N20 X60.
G70 P10 Q20
G73 U3. W0 R2
G73 P10 Q20 U0.4 W0 F0.2
G72 W2. R0.5
G72 P30 Q40 U0.4 W0.1 F0.2
N30 G0 Z-40.
G1 X20.
N40 Z2.
G0 X60. Z2.
G75 R1.
G75 X40. Z-20. P2000 Q3000 F0.1
G0 X0 Z5.
G74 R1.
G74 Z-20. Q5000 F0.1
G97 S600
G0 X30. Z5.
G92 X29. Z-20. F1.5
X28.5
G76 P011060 Q100 R0.05
G76 X27. Z-20. P1000 Q400 F1.5
G98 G1 X60. F100.
G99 G1 Z10. F0.2
M30
"""

# Fanuc's table: the number a function has in system A -> its number in B and in C, where they
# differ (G50 here is the spindle clamp, G90 G92 G94 the single cycles, G98 G99 the feed modes).
RENAME = {
    "B": {"50": "92", "90": "77", "92": "78", "94": "79", "98": "94", "99": "95"},
    "C": {"50": "92", "90": "20", "92": "21", "94": "24", "70": "72", "71": "73", "72": "74", "73": "75",
          "74": "76", "75": "77", "76": "78", "98": "94", "99": "95"},
}
# Power-up modes of the twins: absolute (G90 exists in B and C), feed per revolution, metric
# (G21 in B, G71 in C).
STARTUP = {"B": "G18 G21 G40 G90 G95 G97", "C": "G18 G71 G40 G90 G95 G97"}


def in_system(program: str, system: str) -> str:
    table = RENAME[system]
    return re.sub(r"G(\d+)", lambda m: "G" + table.get(m.group(1), m.group(1)), program)


def twin(tmp: pathlib.Path, system: str) -> pathlib.Path:
    text = LATHE.read_text()
    text = text.replace('gcode_system = "A"', f'gcode_system = "{system}"', 1)
    text = re.sub(r'startup_gcodes = "[^"]*"', f'startup_gcodes = "{STARTUP[system]}"', text, count=1)
    path = tmp / f"lathe_{system.lower()}.toml"
    path.write_text(text)
    return path


def records(nckit: str, program: pathlib.Path, machine: pathlib.Path) -> list:
    run = run_nckit(nckit, "moves", program, "--machine", machine, "--json", text=True)
    check(run.returncode == 0, f"{program.name} on {machine.name} runs ({run.stderr.strip()[:200]})")
    return [json.loads(line) for line in run.stdout.splitlines() if line.strip()]


def check_systems(nckit: str, tmp: pathlib.Path) -> None:
    part_a = tmp / "part_a.nc"
    part_a.write_text(PART_A)
    reference = records(nckit, part_a, LATHE)
    kinds = {r["kind"] for r in reference}
    check({"rapid", "linear", "sync"} <= kinds, f"the part cuts, rapids and threads ({sorted(kinds)})")
    check(len(reference) > 250, f"the cycles expand into moves ({len(reference)} records)")
    for system in ("B", "C"):
        program = tmp / f"part_{system.lower()}.nc"
        program.write_text(in_system(PART_A, system))
        got = records(nckit, program, twin(tmp, system))
        check(len(got) == len(reference), f"system {system}: {len(got)} records, system A {len(reference)}")
        for i, (a, b) in enumerate(zip(reference, got)):
            a = {k: v for k, v in a.items() if k != "line"}
            b = {k: v for k, v in b.items() if k != "line"}
            if a != b:
                check(False, f"system {system}, record {i + 1}: {json.dumps(b)} differs from A's {json.dumps(a)}")
                break
    # The name in an error is the system's own: C's turning cycle is G20.
    system_c = twin(tmp, "C")
    bad = tmp / "c_turning.nc"
    bad.write_text("G0 X60. Z2.\nG20 X50. F0.2\nM30\n")
    run = run_nckit(nckit, "plan", bad, "--machine", system_c, text=True)
    check(run.returncode == 2 and "c_turning.nc:2:1: error: G20 needs both X (U) and Z (W)" in run.stderr,
          f"system C names its own G20 ({run.stderr.strip()})")


# One malformed use per code: program, the FILE:LINE:COL: error: it must give.
MALFORMED = {
    "g92.nc": ("G0 X60. Z2.\nG92 X50. Z-10.\nM30\n", "g92.nc:2:1: error: G92 needs the thread lead F"),
    "g94.nc": ("G0 X60. Z2.\nG94 X20.\nM30\n", "g94.nc:2:1: error: G94 needs both X (U) and Z (W)"),
    "g70.nc": ("G0 X60. Z2.\nG70 P10\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n", "g70.nc:2:1: error: G70 needs both P and Q"),
    "g72.nc": ("G0 X60. Z2.\nG72 W2. R0.5\nG72 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 Z-20.\nG1 X30.\nZ-10.\n"
               "X20. Z-15.\nN20 Z2.\nM30\n", "g72.nc:7:1: error: G72 type I"),
    "g73.nc": ("G73 U1. W1. R0\nM30\n", "g73.nc:1:13: error: G73 R (passes)"),
    "g74.nc": ("G74 R-1.\nM30\n", "g74.nc:1:5: error: G74 R (retract)"),
    "g75.nc": ("G0 X42. Z-10.\nG75 X30. Z-14. P2000 F0.05\nM30\n", "g75.nc:2:1: error: G75 needs the step across"),
    "g75_relief.nc": ("G0 X42. Z-10.\nG75 X30. Z-14. P2000 Q3000 R-1. F0.05\nM30\n",
                      "g75_relief.nc:2:28: error: G75 R (relief at the bottom) must not be negative"),
    "g76.nc": ("G76 P1234567\nM30\n", "g76.nc:1:5: error: G76 P is six digits"),
    "g76_one_block.nc": ("G0 X24. Z5.\nG76 X18. Z-20. K0 D0.4 F1.5\nM30\n", "g76_one_block.nc:2:16: error: G76:"),
    "g50.nc": ("G50 S-100\nM30\n", "g50.nc:1:5: error:"),
    "g77.nc": ("G0 X60. Z2.\nG77 X50. Z-10. F0.2\nM30\n", "g77.nc:2:1: error: G77 does not exist in lathe G-code system A"),
    "u_and_x.nc": ("G28 U0 X0\nM30\n", "u_and_x.nc:1:8: error: U and X both give X"),
    "offset_variable.nc": ("#2401 = 1\nM30\n", "offset_variable.nc:1:1: error: alarm 115"),
    "g10_tip.nc": ("G10 P1 Q12\nM30\n", "g10_tip.nc:1:8: error: G10 Q is a tip orientation"),
    "nose_on_arc.nc": ("G97 S500 M3\nT0101\nG0 X40. Z2.\nG42 G2 X30. Z-5. R5. F0.2\nG1 Z-20.\nG40 G0 X50.\nM30\n",
                       "nose_on_arc.nc:4:1: error: cutter compensation cannot start on an arc"),
}


def check_malformed(nckit: str, tmp: pathlib.Path) -> None:
    tools = tmp / "tools.toml"
    tools.write_text("[[tool]]\nnumber = 1\nnose_radius_mm = 0.4\norientation = 3\n")
    for name, (text, where) in MALFORMED.items():
        path = tmp / name
        path.write_text(text)
        run = run_nckit(nckit, "plan", path, "--machine", LATHE, "--tools", tools, text=True)
        check(run.returncode == 2 and where in run.stderr, f"{name}: {where} exit 2 ({run.stderr.strip()})")
        check(run.stdout == "", f"{name}: no report")
    bad_tools = tmp / "bad_tools.toml"
    bad_tools.write_text("[[tool]]\nnumber = 1\nnose_radius_mm = 0.4\norientation = 12\n")
    path = tmp / "t0101.nc"
    path.write_text("T0101\nM30\n")
    run = run_nckit(nckit, "plan", path, "--machine", LATHE, "--tools", bad_tools, text=True)
    check(run.returncode == 2 and "bad_tools.toml:4:" in run.stderr and "error: 'orientation' is a tip orientation 0 to 9"
          in run.stderr, f"a tip orientation 12 in the tool file: exit 2 at its line ({run.stderr.strip()})")


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        check_systems(nckit, pathlib.Path(tmp))
        check_malformed(nckit, pathlib.Path(tmp))
    return summary()


if __name__ == "__main__":
    sys.exit(main())
