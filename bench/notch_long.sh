#!/usr/bin/env bash
# `nckit notch` on long generated programs (docs/processes/notching.md, "Long programs"): N
# notches 0.5 mm apart along X, each after F filler moves, on the notcher with a long X travel.
# Prints wall time and peak memory of `nckit notch --json` for each program.
# Usage: bash bench/notch_long.sh [NCKIT]
set -euo pipefail
nckit=${1:-build/release/src/nckit}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed '0,/max = 1200.0/s//max = 200000.0/' examples/machines/notcher.toml >"$tmp/notcher.toml"
program() {  # notches fillers_per_notch
  python3 - "$1" "$2" <<'PY'
import sys
notches, fillers = int(sys.argv[1]), int(sys.argv[2])
w = sys.stdout.write
w("G90 G1 X0 Z40 F3000\n")
for i in range(notches):
    x = 10 + 0.5 * i
    for k in range(fillers):
        w(f"G1 X{x - 0.25:.3f} Z{40 + (k % 2):d} F3000\n")
    w(f"G0 X{x:.3f} Z30\nG1 Z20 F4000\nM27\nG1 Z8 F900\nM28\n")
w(f"G0 X{10 + 0.5 * notches + 5:.3f} Z40\nM30\n")
PY
}
run() {  # label notches fillers_per_notch
  program "$2" "$3" >"$tmp/p.nc"
  /usr/bin/time -f "%e s %M KB" -o "$tmp/time" "$nckit" notch "$tmp/p.nc" --machine "$tmp/notcher.toml" --json \
    >/dev/null 2>"$tmp/err" || echo "failed: $(head -c 300 "$tmp/err")"
  printf '%-44s %8s lines  %s\n' "$1" "$(wc -l <"$tmp/p.nc")" "$(tail -n1 "$tmp/time")"
}
run "100 notches" 100 1
run "100 notches among 300,000 filler blocks" 100 3000
run "10,000 notches" 10000 0
[ "${SKIP_100K:-}" ] || run "100,000 notches" 100000 0
