#!/usr/bin/env python3
"""The example lathe as a user runs it: a Fanuc program without G98/G99 feeds per revolution
and `nckit plan` times it from the spindle speed; a code of another G-code system, a bad
cycle (the one-block forms' words among them) and a bad offset write stop with FILE:LINE:COL: error: and exit status 2.
On the Haas lathe G71's words on G70 run with a warning; a Haas lathe in system B and a G70
with an address and no number stop with exit status 2."""
import json
import pathlib
import sys
import tempfile

from cli_checks import check, run_nckit, summary

ROOT = pathlib.Path(__file__).resolve().parents[2]
LATHE = ROOT / "examples" / "machines" / "lathe.toml"
HAAS = ROOT / "examples" / "machines" / "haas_lathe.toml"
HAAS_G70 = "G97 S500 M03\nG00 X2. Z0.1\nG71 P10 Q20 U0.02 W0 D0.1 F0.01\nN10 G00 X1.\nG01 Z-1.\nN20 X2.\n"


def check_haas(nckit: str, tmp: pathlib.Path) -> None:
    """The Haas lathe: G71's U W D on G70 are read with a warning and the program plans; the same
    block on the Fanuc lathe, a Haas key on a system-B lathe and `G70 P10 Q` are errors."""
    program = tmp / "haas_g70.nc"
    program.write_text(HAAS_G70 + "G70 P10 Q20 U0.02 W0 D0.05 F0.005\nM30\n")
    run = run_nckit(nckit, "plan", program, "--machine", HAAS, "--json", text=True)
    check(run.returncode == 0, f"Haas G70 with U W D plans ({run.stderr.strip()})")
    check("haas_g70.nc:7:13: warning: G70 does not use U W D" in run.stderr,
          f"the ignored words are reported at the U ({run.stderr.strip()})")
    run = run_nckit(nckit, "plan", program, "--machine", LATHE, text=True)
    check(run.returncode == 2 and "haas_g70.nc:7:13: error:" in run.stderr, "the Fanuc lathe refuses them")
    no_q = tmp / "haas_no_q.nc"
    no_q.write_text(HAAS_G70 + "G70 P10 Q\nM30\n")
    run = run_nckit(nckit, "plan", no_q, "--machine", HAAS, text=True)
    check(run.returncode == 2 and "haas_no_q.nc:7:" in run.stderr and ": error:" in run.stderr,
          f"G70 P10 Q: exit 2 ({run.stderr.strip()})")
    system_b = tmp / "haas_b.toml"
    system_b.write_text(HAAS.read_text().replace('gcode_system = "A"', 'gcode_system = "B"')
                        .replace("G20 G40 G97 G99", "G20 G40 G90 G95 G97"))
    run = run_nckit(nckit, "plan", program, "--machine", system_b, text=True)
    check(run.returncode == 2 and "haas_b.toml:10:17: error:" in run.stderr,
          f"lathe_control = haas in system B: exit 2 at the key ({run.stderr.strip()})")
    check(run.stdout == "", "no report from a bad machine file")


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        program = pathlib.Path(tmp) / "per_rev.nc"
        # 500 rpm, F0.2: per revolution 100 mm/min, so the 50 mm cut alone takes 30 s. Read as
        # per minute (G94 at power-up) it would take 250 minutes.
        program.write_text("O1000\nG97 S500 M03\nG00 X40. Z2.\nG01 Z-48. F0.2\nG00 X60.\nM30\n")
        run = run_nckit(nckit, "plan", program, "--machine", LATHE, "--json", text=True)
        check(run.returncode == 0, f"the program plans ({run.stderr.strip()})")
        if run.returncode == 0:
            report = json.loads(run.stdout)
            cycle = report["cycle_time_s"]
            check(30.0 <= cycle <= 32.0, f"cycle time {cycle:.3f} s is the 30 s cut plus its rapids")
        # The same program with G98: F0.2 mm/min would be 250 min; nckit plans it as written.
        per_min = pathlib.Path(tmp) / "per_min.nc"
        per_min.write_text("G98 G97 S500 M03\nG00 X40. Z2.\nG01 Z-48. F100.\nM30\n")
        run = run_nckit(nckit, "plan", per_min, "--machine", LATHE, "--json", text=True)
        check(run.returncode == 0, "G98 plans")
        if run.returncode == 0:
            cycle = json.loads(run.stdout)["cycle_time_s"]
            check(30.0 <= cycle <= 31.0, f"G98 F100: 50 mm at 100 mm/min ({cycle:.3f} s)")

        cases = {
            "g91.nc": ("G0 X10.\nG91 U1.\nM30\n", "g91.nc:2:1: error:"),
            "g95.nc": ("G95 F0.2\nM30\n", "g95.nc:1:1: error:"),
            "cycle.nc": ("G0 X60. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U-0.4 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n",
                         "cycle.nc:3:13: error:"),
            "offset.nc": ("G10 P200 X1.\nM30\n", "offset.nc:1:5: error:"),
            "g90.nc": ("G0 X60. Z2.\nG90 X50. F0.2\nM30\n", "g90.nc:2:1: error:"),
            # The one-block forms: R other than R1 on G71 P Q, G73 P Q I without D, D on a first
            # block, and G71's words on G70.
            "g71r.nc": ("G0 X60. Z2.\nG71 P10 Q20 U0.4 D2. R0.5 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n",
                        "g71r.nc:2:22: error:"),
            "g73i.nc": ("G0 X60. Z2.\nG73 P10 Q20 I3. U0.4 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n",
                        "g73i.nc:2:13: error:"),
            "g71d.nc": ("G71 U2. R0.5 D1.\nM30\n", "g71d.nc:1:14: error:"),
            "g70u.nc": ("G0 X60. Z2.\nG70 P10 Q20 U0 W0 D0.01\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n",
                        "g70u.nc:2:13: error:"),
        }
        for name, (text, where) in cases.items():
            path = pathlib.Path(tmp) / name
            path.write_text(text)
            run = run_nckit(nckit, "plan", path, "--machine", LATHE, text=True)
            check(run.returncode == 2 and where in run.stderr, f"{name}: {where} exit 2 ({run.stderr.strip()})")
            check(run.stdout == "", f"{name}: no report")
        check_haas(nckit, pathlib.Path(tmp))
    return summary()


if __name__ == "__main__":
    sys.exit(main())
