#!/usr/bin/env python3
"""Writes the planner's limit and cycle-time programs (deterministic: regenerating gives the same files).

  semicircles_100.ngc  100 alternating tangent semicircles, r 3.5-4 mm, G2/G3 in turn, F3000
  slot.ngc             line - arc (r 5) - line slot; F given by the caller's copy (F3000 here)
  slot_f6000.ngc       the same at F6000
  circle_g2.ngc        a full circle r 20 as one G2, F3000
  circle_8arcs.ngc     the same circle as 8 G2 arcs, end points and I/J rounded to 3 decimals
  raster_3d.ngc        2,000 G1 moves: 20 zig-zag rows of 99 segments over a smooth Z surface,
                       4 decimals, G64 P0.01, F3000
Every program starts with G64 P0.01 (path tolerance 0.01 mm), like square_100.ngc and
circle_2000.ngc beside it.

Usage: bench/planner_programs/gen_limit_programs.py [OUT_DIR]   (default: this script's folder)
"""
import math
import os
import sys

HEAD = ["%", "G21 G17 G90 G94", "G64 P0.01"]


def fmt(value, decimals):
    text = f"{value:.{decimals}f}"
    return "0." if text.strip("-0.") == "" else text


def semicircles(count=100):
    lines = HEAD[:1] + [f"({count} alternating tangent semicircles, r 3.5-4 mm, F3000)"] + HEAD[1:]
    x = 0.0
    for k in range(count):
        r = 3.5 + 0.5 * ((k * 7) % 11) / 10.0
        word = "G2" if k % 2 == 0 else "G3"
        end = x + 2 * r
        feed = " F3000" if k == 0 else ""
        lines.append(f"{word} X{fmt(end, 4)} Y0. I{fmt(r, 4)} J0.{feed}")
        x = end
    return lines + ["M2", "%"]


def slot(feed):
    return HEAD[:1] + [f"(line - arc r5 - line slot at F{feed})"] + HEAD[1:] + [
        f"G1 X50. Y0. F{feed}", "G3 X50. Y10. I0. J5.", "G1 X0. Y10.", "M2", "%"]


def circle_g2():
    return HEAD[:1] + ["(full circle r 20 as one G2, centre X20 Y0)"] + HEAD[1:] + [
        "G2 X0. Y0. I20. J0. F3000", "M2", "%"]


def circle_8arcs():
    lines = HEAD[:1] + ["(circle r 20 as 8 G2 arcs, end points and centres at 3 decimals)"] + HEAD[1:]
    cx, r = 20.0, 20.0
    prev = (0.0, 0.0)
    for k in range(1, 9):
        angle = math.pi - 2 * math.pi * k / 8   # clockwise from the leftmost point
        end = (round(cx + r * math.cos(angle), 3), round(r * math.sin(angle), 3))
        if k == 8:
            end = (0.0, 0.0)
        i, j = round(cx - prev[0], 3), round(0.0 - prev[1], 3)
        feed = " F3000" if k == 1 else ""
        lines.append(f"G2 X{fmt(end[0], 3)} Y{fmt(end[1], 3)} I{fmt(i, 3)} J{fmt(j, 3)}{feed}")
        prev = end
    return lines + ["M2", "%"]


def raster():
    rows, cols, step_x, step_y = 20, 99, 0.5, 1.0
    lines = HEAD[:1] + ["(3D raster: 20 zig-zag rows of 99 G1 segments over a smooth surface, 2,000 moves)"] + HEAD[1:]

    def z_at(x, y):
        return 2.0 * math.sin(x / 8.0) * math.cos(y / 6.0)

    moves = 0
    first = True
    for row in range(rows):
        y = row * step_y
        xs = [c * step_x for c in range(cols + 1)]
        if row % 2:
            xs.reverse()
        start = 0 if row == 0 else 1
        if row > 0:
            lines.append(f"G1 Y{fmt(y, 4)} Z{fmt(z_at(xs[0], y), 4)}")
            moves += 1
        for x in xs[start:]:
            feed = " F3000" if first else ""
            first = False
            lines.append(f"G1 X{fmt(x, 4)} Y{fmt(y, 4)} Z{fmt(z_at(x, y), 4)}{feed}")
            moves += 1
    assert moves == 2000, moves
    return lines + ["M2", "%"]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    programs = {
        "semicircles_100.ngc": semicircles(),
        "slot.ngc": slot(3000),
        "slot_f6000.ngc": slot(6000),
        "circle_g2.ngc": circle_g2(),
        "circle_8arcs.ngc": circle_8arcs(),
        "raster_3d.ngc": raster(),
    }
    for name, lines in programs.items():
        with open(os.path.join(out, name), "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
