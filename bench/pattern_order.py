#!/usr/bin/env python3
"""Cut order of the shoe-sole example for every size: air distance, air time and reversals in
drawing order and optimised, the lower bound and the optimised order's distance above it, the
planned cycle time, and the wall time of one `nckit pattern` run per size (layout, order,
bound, program and plan). Prints a Markdown table for BENCHMARKS.md.

usage: python3 bench/pattern_order.py [build/release/src/nckit]"""
import json
import os
import subprocess
import sys
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
nckit = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/release/src/nckit")
job = os.path.join(root, "examples/pattern/sole_pattern.toml")
machine = os.path.join(root, "examples/pattern/stepper_mill.toml")

print("| size | grooves | drawing order: air mm / s / reversals | optimised: air mm / s / reversals "
      "| bound mm / s | above bound (distance / time) | planned cycle s (air s) | run s |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for size, extra in [("38", []), ("40", []), ("40", ["--mirror"]), ("42", []), ("44", [])]:
    start = time.perf_counter()
    r = subprocess.run([nckit, "pattern", job, "--machine", machine, "--size", size, *extra, "--json"],
                       capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    s = json.loads(r.stdout)["sizes"][0]
    d, o, b = s["drawing_order"], s["optimised_order"], s["bound"]
    print(f"| {size}{' mirrored' if extra else ''} | {s['cuts']} "
          f"| {d['air_distance_mm']:.0f} / {d['air_time_s']:.1f} / {d['reversals']} "
          f"| {o['air_distance_mm']:.0f} / {o['air_time_s']:.1f} / {o['reversals']} "
          f"| {b['air_distance_mm']:.0f} / {b['air_time_s']:.1f} "
          f"| {100 * s['gap_to_bound']['air_distance']:.1f} % / {100 * s['gap_to_bound']['air_time']:.1f} % "
          f"| {s['planned']['cycle_time_s']:.1f} ({s['planned']['air_time_s']:.1f}) | {wall:.2f} |")
