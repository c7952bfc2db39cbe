#!/usr/bin/env bash
# Cycle times of the planner programs against the grid TOPP optimum (bench/topp_reference.py):
# nckit trapezoid against it, nckit S-curve at j 50,000 and 5,000 mm/s³ for reference; 100 mm/s
# and 500 mm/s² per axis. The S-curve columns are compared with the jerk-limited reference in
# bench/scurve_reference.sh (topp_reference.py --jmax leaves out the path jerk q'·s⃛).
# Prints a Markdown table. Usage: bench/planner_optimum.sh [NCKIT_BINARY]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
nckit=${1:-$repo/build/release/src/nckit}
programs=$repo/bench/planner_programs
work=$(mktemp -d -t nckit-optimum-XXXXXX)
trap 'rm -rf "$work"' EXIT
source "$repo/bench/planner_machines.sh"
write_planner_machines "$work"
cycle() { "$nckit" plan "$programs/$1" --machine "$work/j$2.toml" --profile "$3" --json |
          python3 -c 'import json,sys; print("%.3f" % json.load(sys.stdin)["cycle_time_s"])'; }
echo "| program | optimum (s) | nckit trapezoid (s) | ratio | S-curve j 50,000 (s) | S-curve j 5,000 (s) |"
echo "|---|---:|---:|---:|---:|---:|"
reference() {  # PROGRAM: seconds, with the number of corner stops when there are any
  python3 "$repo/bench/topp_reference.py" "$programs/$1" --max-points 1000000 "${@:2}" |
    python3 -c 'import json,sys; r=json.load(sys.stdin); print("%.3f%s" % (r["time_s"], " (exact path, %d stops)" % r["corners"] if r["corners"] else ""))'
}
ratio() { python3 -c "print('%.3f' % ($1 / float('$2'.split()[0])))"; }
for prog in circle_g2 circle_2000 semicircles_100 square_100 slot slot_f6000 raster_3d circle_8arcs; do
  trap_s=$(cycle "$prog.ngc" 50000 trapezoid)
  s50=$(cycle "$prog.ngc" 50000 scurve)
  s5=$(cycle "$prog.ngc" 5000 scurve)
  # Polylines: their optimum is the best curve within G64 P, which the grid reference (it follows
  # the programmed path and stops at corners) does not compute.
  if [[ $prog == circle_2000 || $prog == raster_3d ]]; then
    echo "| $prog | not computed | $trap_s | | $s50 | $s5 |"
    continue
  fi
  opt=$(reference "$prog.ngc")
  echo "| $prog | $opt | $trap_s | $(ratio "$trap_s" "$opt") | $s50 | $s5 |"
done
