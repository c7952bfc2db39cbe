#!/usr/bin/env bash
# nckit on the largest G5.2 NURBS curve it reads (LinuxCNC dialect): 19,991 control points of
# order 3, every one of weight 1, a sine along X. Prints the wall time and peak memory of
# `nckit check` and `nckit moves` (each spline point costs k^2 basis terms, not k times the
# number of control points: docs/gcode-linuxcnc.md, "Splines").
# Usage: bench/nurbs_large.sh [NCKIT] [POINTS]   (default build/release/src/nckit, 19991)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
nckit=${1:-$here/../build/release/src/nckit}
points=${2:-19991}
die() { echo "nurbs_large: $*" >&2; exit 1; }
[[ -x $nckit ]] || die "nckit binary '$nckit' not found: build it (make build) or pass its path"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: run scripts/deps.sh (installs time)"

work=$(mktemp -d -t nckit-nurbs-XXXXXX)
trap 'rm -rf "$work"' EXIT
program=$work/nurbs.ngc
python3 - "$points" >"$program" <<'PY'
import math, sys
points = int(sys.argv[1])
print("G21 G17 G90 F1000")
print("G0 X0 Y0")
print("G5.2 X0 Y0 P1 L3")
for i in range(1, points):
    print(f"X{i * 0.02:.4f} Y{5 * math.sin(i * 0.01):.4f} P1")
print("G5.3")
print("M2")
PY
for verb in check moves; do
  /usr/bin/time -f "%e %M" -o "$work/time" "$nckit" "$verb" "$program" --dialect linuxcnc >"$work/out" \
    || die "nckit $verb failed"
  read -r wall_s peak_kb <"$work/time"
  echo "nckit $verb, $points control points: ${wall_s} s, peak ${peak_kb} kB, $(wc -l <"$work/out") lines out"
done
