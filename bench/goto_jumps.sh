#!/usr/bin/env bash
# GOTO across a long program (docs/cli-safety.md): the runaway `N1 GOTO2`, 10,000 empty lines,
# `N2 GOTO1` until alarm 100 (default --max-blocks 10,000,000), and a loop of 2,000 round trips
# over 100,000 lines that ends normally. Prints wall time and peak memory of `nckit moves`.
# Usage: bash bench/goto_jumps.sh [NCKIT]
set -euo pipefail
nckit=${1:-build/release/src/nckit}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
{ echo "N1 GOTO2"; printf '\n%.0s' $(seq 10000); echo "N2 GOTO1"; } >"$tmp/runaway.nc"
{ echo "#1=0"; echo "N1 #1=#1+1"; echo "IF [#1 GE 2000] GOTO3"; echo "GOTO2";
  printf 'G4 P0\n%.0s' $(seq 100000); echo "N2 GOTO1"; echo "N3 G1 X[#1/100] F100"; echo "M30"; } >"$tmp/trips.nc"
run() {
  local what=$1; shift
  /usr/bin/time -f "%e s %M KB" -o "$tmp/time" "$nckit" moves "$@" >/dev/null 2>"$tmp/err" || true
  printf '%-52s %s  %s\n' "$what" "$(tail -n1 "$tmp/time")" "$(grep -o 'alarm [0-9]*' "$tmp/err" | head -1)"
}
run "runaway ping-pong over 10,000 lines (to alarm 100)" "$tmp/runaway.nc"
run "2,000 round trips over 100,000 lines" "$tmp/trips.nc"
