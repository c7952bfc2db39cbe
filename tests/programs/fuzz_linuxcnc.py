#!/usr/bin/env python3
"""Seeded differential fuzzer: random programs of the subset nckit and LinuxCNC read alike, run
through `rs274 -g` and `nckit moves --json` by compare_linuxcnc.py, which must find them equal.

Each program (`NN_fuzz.ngc`, seed + index) mixes: rapids and feeds in absolute and incremental
mode, arcs by I J (with end points rounded to 3 decimals, as CAM output is) and by R (both
signs), helices, the three planes, G20/G21, work offsets G10 L2 + G54-G59, G92, number
spellings (`X1.`, `X.5`, `X-0.25`), and drilling cycles G81 G82 G83 G73 G85 G89 with G98/G99,
incremental repeats and `G0 G80`. The dialect differences of docs/gcode-mill.md (power-on
retract mode, cycle P units, G76/G87) are avoided: every cycle block states G98 or G99.

Usage: fuzz_linuxcnc.py --count N [--seed S] [--nckit BIN] [--keep DIR]
Exit status 0 when every program matches.
"""
from __future__ import annotations

import argparse
import math
import random
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def num(rng: random.Random, v: float, decimals: int = 3) -> str:
    text = f"{v:.{decimals}f}"
    if rng.random() < 0.2 and "." in text:  # `1.` and `.5` spellings
        text = text.rstrip("0")
        if text.startswith("0.") and rng.random() < 0.5:
            text = text[1:]
        elif text.startswith("-0.") and rng.random() < 0.5:
            text = "-" + text[2:]
        if text in (".", "-.", "0.", "-0.", ""):
            text = "0"
    return text


def program(rng: random.Random) -> str:
    out = ["G21 G17 G90 G94 G40 G49 G80", "G0 X0 Y0 Z20", "S1000 M3", "F300"]
    pos = {"X": 0.0, "Y": 0.0, "Z": 20.0}
    for _ in range(rng.randint(8, 25)):
        kind = rng.choice(["line", "line", "arc_ij", "arc_r", "cycle", "offset", "plane", "units"])
        if kind == "line":
            code = rng.choice(["G0", "G1"])
            words = []
            for a in rng.sample("XYZ", rng.randint(1, 3)):
                pos[a] = round(rng.uniform(-40, 40) if a != "Z" else rng.uniform(-5, 30), 3)
                words.append(a + num(rng, pos[a]))
            out.append(" ".join([code] + words))
        elif kind in ("arc_ij", "arc_r"):
            r = rng.uniform(2, 20)
            a0, sweep = rng.uniform(0, 2 * math.pi), rng.uniform(0.3, 2.8)
            cx, cy = pos["X"] - r * math.cos(a0), pos["Y"] - r * math.sin(a0)
            d = rng.choice(["G2", "G3"])
            a1 = a0 - sweep if d == "G2" else a0 + sweep
            ex, ey = round(cx + r * math.cos(a1), 3), round(cy + r * math.sin(a1), 3)
            words = [d, "X" + num(rng, ex), "Y" + num(rng, ey)]
            if rng.random() < 0.3:
                pos["Z"] = round(pos["Z"] - rng.uniform(0, 2), 3)
                words.append("Z" + num(rng, pos["Z"]))
            if kind == "arc_ij":
                words += ["I" + num(rng, cx - pos["X"], 4), "J" + num(rng, cy - pos["Y"], 4)]
            else:
                chord = math.hypot(ex - pos["X"], ey - pos["Y"])
                rr = max(r, chord / 2 + 0.001)
                words.append("R" + num(rng, rr if sweep <= math.pi else -rr, 4))
            pos["X"], pos["Y"] = ex, ey
            out.append(" ".join(words))
        elif kind == "cycle":
            cyc = rng.choice(["G81", "G82", "G83", "G73", "G85", "G89"])
            ret = rng.choice(["G98", "G99"])
            r_level = round(rng.uniform(1, 5), 3)
            bottom = round(rng.uniform(-8, 0), 3)
            out.append("G0 Z" + num(rng, 25))
            words = [ret, cyc, "X" + num(rng, rng.uniform(-30, 30)), "Y" + num(rng, rng.uniform(-30, 30)),
                     "Z" + num(rng, bottom), "R" + num(rng, r_level), "F120"]
            if cyc in ("G83", "G73"):
                words.append("Q" + num(rng, rng.uniform(0.7, 3)))
            if cyc in ("G82", "G89"):
                words.append("P0.2")
            out.append(" ".join(words))
            if rng.random() < 0.5:
                out.append("X" + num(rng, rng.uniform(-30, 30)))
            if rng.random() < 0.4:
                out.append(f"G91 {ret} X5 Y-3 L{rng.randint(1, 3)}")
                out.append("G90")
            out.append("G0 G80 Z25" if rng.random() < 0.5 else "G80")
            out.append("G0 Z25")
            out.append("G0 X0 Y0")
            pos.update({"X": 0.0, "Y": 0.0, "Z": 25.0})
        elif kind == "offset":
            n = rng.randint(1, 6)
            out.append(f"G10 L2 P{n} X{num(rng, rng.uniform(-20, 20))} Y{num(rng, rng.uniform(-20, 20))}")
            out.append(f"G{53 + n}")
            out.append(f"G0 X{num(rng, pos['X'])} Y{num(rng, pos['Y'])}")
        elif kind == "plane":
            out.append(rng.choice(["G18", "G19"]) + " G1 Z" + num(rng, pos["Z"]))
            out.append("G17")
        else:
            out.append(f"G20 G0 X{num(rng, pos['X'] / 25.4, 4)} Y{num(rng, pos['Y'] / 25.4, 4)}")
            out.append("G21 G0 X" + num(rng, pos["X"]) + " Y" + num(rng, pos["Y"]))
    out += ["G54", "G0 Z30", "M5", "M2"]
    return "\n".join(out) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=20)
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--nckit", default=None)
    ap.add_argument("--keep", type=Path, default=None, help="write the programs here and keep them")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.keep or Path(scratch)
        folder.mkdir(parents=True, exist_ok=True)
        for i in range(args.count):
            rng = random.Random(args.seed * 1_000_003 + i)
            (folder / f"{i:05d}_fuzz.ngc").write_text(program(rng))
        cmd = [sys.executable, str(HERE / "compare_linuxcnc.py"), "--programs", str(folder)]
        if args.nckit:
            cmd += ["--nckit", args.nckit]
        return subprocess.run(cmd).returncode


if __name__ == "__main__":
    sys.exit(main())
