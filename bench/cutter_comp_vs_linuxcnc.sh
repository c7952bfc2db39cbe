#!/usr/bin/env bash
# Cutter radius compensation throughput, nckit against LinuxCNC: both read the same program of
# 200,000 G1 blocks with G41.1 on (400 laps of a 7-lobed closed contour, 500 blocks a lap, tool
# radius 2 mm) and write their motions to /dev/null. Best wall time and peak RSS of 3 runs each.
#
# Usage: flock /tmp/nckit-linuxcnc.lock bench/cutter_comp_vs_linuxcnc.sh [NCKIT_BINARY]
# Needs rs274 (linuxcnc-uspace) and /usr/bin/time (package time): scripts/deps.sh installs both.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
nckit=${1:-$repo/build/release/src/nckit}
runs=3
blocks=200000

die() { echo "cutter_comp_vs_linuxcnc: $*" >&2; exit 1; }
[[ -x $nckit ]] || die "nckit binary '$nckit' not found: build it (make build) or pass its path"
nckit=$(cd "$(dirname "$nckit")" && pwd)/$(basename "$nckit")
rs274=$(command -v rs274) || die "rs274 not on PATH: run scripts/deps.sh (installs linuxcnc-uspace)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: run scripts/deps.sh (installs time)"

work=$(mktemp -d -t nckit-cutcomp-XXXXXX)
trap 'rm -rf "$work"' EXIT
program=$work/lobes_200k.ngc

LC_ALL=C awk -v n=$blocks 'BEGIN {
  pi = atan2(0, -1)
  print "G21 G17 G90 G94 F1000"
  print "G0 X-10 Y-10 Z0"
  print "G41.1 D4 G1 X0 Y0"
  for (i = 1; i < n; i++) {
    a = 2 * pi * i / 500
    r = 50 + 10 * sin(7 * a)
    printf "G1 X%.4f Y%.4f\n", r * cos(a), r * sin(a)
  }
  print "G40 G1 X-10 Y-10"
  print "M2"
}' > "$program"

script_name=cutter_comp_vs_linuxcnc
# shellcheck source=bench/best_of.sh
source "$repo/bench/best_of.sh"

moves_vs_rs274 "$program" "$blocks" "G41.1 lobed contour"
