#!/usr/bin/env python3
"""Writes surface_50k.ngc: a finishing raster the way CAM output looks.

Zig-zag rows along X over a smooth bump, z = -2 + 3 exp(-r^2 / (2 * 8^2)) with r the distance
from (20, 12.5): 125 rows of 400 G1 segments 0.1 mm long, 0.2 mm step-over (X 0..40, Y 0..24.8),
X Y with 3 decimals and Z with 4, words that do not change left out, F3000 on the first feed,
G64 P0.01. 50,125 G1 blocks (with the plunge and the step-overs), about 1 MB; deterministic (no randomness), so regenerating gives
the same file.

Usage: bench/planner_programs/gen_surface.py [OUT]   (default: surface_50k.ngc beside this script)
"""
import math
import os
import sys

ROWS, COLS = 125, 400        # 125 x 400 = 50,000 segments along the rows
STEP_X, STEP_Y = 0.1, 0.2    # mm


def z_at(x, y):
    r2 = (x - 20.0) ** 2 + (y - 12.5) ** 2
    return -2.0 + 3.0 * math.exp(-r2 / (2 * 8.0 ** 2))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "surface_50k.ngc")
    lines = ["%", f"(finishing raster over a bump: {ROWS} rows of {COLS} G1 segments)",
             "G21 G17 G90 G94", "G64 P0.01", "G0 Z5.", "G0 X0. Y0."]
    last = {}

    def emit(word_values, feed=None):
        words = []
        for axis, fmt, value in word_values:
            text = f"{value:.{fmt}f}"
            if text == "-0." + "0" * fmt:
                text = "0." + "0" * fmt
            if last.get(axis) != text:
                words.append(f"{axis}{text}")
                last[axis] = text
        if feed:
            words.append(f"F{feed}")
        if words:
            lines.append("G1 " + " ".join(words))

    last.update({"X": "0.000", "Y": "0.000"})
    emit([("Z", 4, z_at(0.0, 0.0))], feed=3000)  # plunge onto the surface
    for j in range(ROWS):
        y = j * STEP_Y
        cols = range(COLS + 1) if j % 2 == 0 else range(COLS, -1, -1)
        for n, i in enumerate(cols):
            x = i * STEP_X
            if n == 0 and j == 0:
                continue
            emit([("X", 3, x), ("Y", 3, y), ("Z", 4, z_at(x, y))])
    lines += ["G0 Z5.", "G0 X0. Y0.", "M2", "%"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
