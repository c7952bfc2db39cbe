#!/usr/bin/env bash
# Runs every benchmark: the in-process Google Benchmark targets, then the side-by-side scripts.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/release
for target in "$build"/bench/*_bench; do
  [[ -x $target ]] || continue
  echo "== $target"
  "$target" --benchmark_min_time=0.5
done
echo "== nckit moves vs LinuxCNC rs274 -g, 1,000,000 G1 blocks"
bash bench/throughput_vs_linuxcnc.sh "$build/src/nckit"
echo "== nckit moves vs LinuxCNC rs274 -g, Macro B WHILE loop with trig, 200,000 iterations"
bash bench/macro_vs_linuxcnc.sh "$build/src/nckit"
if [[ -f /usr/lib/linuxcnc/modules/nckit_cam.so ]]; then
  echo "== nckit_cam in LinuxCNC's halrun: cost per call, the example piston with the loop in HAL"
  python3 bench/hal_cam_bench.py --nckit "$build/src/nckit"
fi
