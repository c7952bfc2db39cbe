#!/usr/bin/env bash
# S-curve cycle times of the planner programs against the jerk-limited reference
# (bench/jerk_reference.py: full per-axis jerk, docs/planner.md "The jerk-limited reference"),
# 100 mm/s, 500 mm/s² and 5,000 or 50,000 mm/s³ per axis. Two references per program:
#   pass  curvature jumps passed with the acceleration step allowed there (a relaxation)
#   stop  curvature jumps taken as exact stops (a feasible trajectory on the exact path)
#   blend curvature jumps replaced by quintics within G64 P0.01 (jerk_reference_blend.py: a
#         feasible trajectory on a path within P)
# Corners stop in both. The circle of 2,000 G1 uses the circle r 20 of circle_g2.ngc, which lies
# within 1e-4 mm of its chords (inside G64 P0.01); the raster uses its rows as the smooth surface
# curve they are chords of (bench/raster_reference.py; within 1e-3 mm), its 90° corners stopped.
# Prints a Markdown table; keeps each reference's JSON in OUT_DIR, and reuses the ones it finds
# there (delete them to recompute).
# Usage: bench/scurve_reference.sh [NCKIT_BINARY] [OUT_DIR]   (about half an hour on 2 cores)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
nckit=${1:-$repo/build/release/src/nckit}
out=${2:-$(mktemp -d -t nckit-jerk-reference-XXXXXX)}
mkdir -p "$out"
programs=$repo/bench/planner_programs
source "$repo/bench/planner_machines.sh"
write_planner_machines "$out"
cycle() { "$nckit" plan "$programs/$1.ngc" --machine "$out/j$2.toml" --profile scurve --json |
          python3 -c 'import json,sys; print("%.3f" % json.load(sys.stdin)["cycle_time_s"])'; }
reference() {  # PROGRAM JERK JOINS: the extrapolated time (the JSON stays in $out)
  local file=$out/$1.j$2.$3.json
  # Up to 8,000 nodes; the semicircles stopped at their joins are 100 short runs of 11 shapes,
  # refined to 2,048 nodes each.
  local most=8000
  [[ $1 == semicircles_100 && $3 == stop ]] && most=64000
  if [[ ! -s $file ]]; then
    if [[ $3 == blend ]]; then
      python3 "$repo/bench/jerk_reference_blend.py" "$programs/$1.ngc" --jmax "$2" --tolerance 0.01 \
        --start-points 2000 --max-points 8000 > "$file.tmp"
    elif [[ $1 == raster_3d ]]; then
      python3 "$repo/bench/raster_reference.py" --jmax "$2" --start-points 8000 --max-points 32000 > "$file.tmp"
    else
      python3 "$repo/bench/jerk_reference.py" "$programs/$1.ngc" --jmax "$2" --joins "$3" \
        --start-points 2000 --max-points "$most" > "$file.tmp"
    fi
    mv "$file.tmp" "$file"
  fi
  python3 -c 'import json,sys; print("%.3f" % json.load(open(sys.argv[1]))["extrapolated_s"])' "$file"
}
ratio() { python3 -c "print('%.3f' % ($1 / $2))"; }
echo "| program | jerk (mm/s³) | nckit S-curve (s) | reference, joins passed (s) | ratio | joins blended within P (s) | ratio | joins stopped (s) | ratio |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for prog in circle_g2 circle_2000 semicircles_100 square_100 slot slot_f6000 raster_3d circle_8arcs; do
  for jerk in 50000 5000; do
    s=$(cycle "$prog" "$jerk")
    if [[ $prog == raster_3d ]]; then  # no curvature jump on the surface curve: one reference
      ref=$(reference "$prog" "$jerk" surface)
      echo "| $prog | $jerk | $s | $ref | $(ratio "$s" "$ref") | $ref | $(ratio "$s" "$ref") | $ref | $(ratio "$s" "$ref") |"
      continue
    fi
    ref_prog=$prog
    [[ $prog == circle_2000 ]] && ref_prog=circle_g2
    pass=$(reference "$ref_prog" "$jerk" pass)
    if python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1]))["curvature_jumps"] == 0)' \
        "$out/$ref_prog.j$jerk.pass.json"; then
      stop=$(reference "$ref_prog" "$jerk" stop)
      blend=$(reference "$ref_prog" "$jerk" blend)
    else
      stop=$pass  # no curvature jump: the same trajectory
      blend=$pass
    fi
    echo "| $prog | $jerk | $s | $pass | $(ratio "$s" "$pass") | $blend | $(ratio "$s" "$blend") | $stop | $(ratio "$s" "$stop") |"
  done
done
echo
echo "| reference | grids (nodes: time s) | last change | extrapolated (s) |"
echo "|---|---|---:|---:|"
for file in "$out"/*.json; do
  python3 - "$file" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))
grids = ", ".join("%d: %.5f" % (n, t) for n, t, _ in r["refinements"])
name = os.path.basename(sys.argv[1])[:-5]
print("| %s | %s | %.1e | %.4f |" % (name, grids, r["last_change"], r["extrapolated_s"]))
PY
done
