#!/usr/bin/env bash
# Cutter radius compensation throughput, nckit against LinuxCNC: both read the same program of
# 200,000 G1 blocks with G41.1 on (400 laps of a 7-lobed closed contour, 500 blocks a lap, tool
# radius 2 mm) and write their motions to /dev/null. Best wall time and peak RSS of 3 runs each.
#
# Usage: flock /tmp/linuxcnc.lock bench/cutter_comp_vs_linuxcnc.sh [NCKIT_BINARY]
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

# Untimed sanity check: both must compensate every block.
rs_moves=$(cd "$work" && "$rs274" -g "$program" 2>/dev/null | grep -c 'STRAIGHT_FEED(\|ARC_FEED(') || true
nc_moves=$("$nckit" moves "$program" | wc -l) || die "nckit moves failed on $program"
((rs_moves >= blocks)) || die "rs274 printed $rs_moves feeds for $blocks G1 blocks"
((nc_moves >= blocks)) || die "nckit printed $nc_moves lines for $blocks G1 blocks"

rs_best=$(best_of "$rs274" -g "$program")
nc_best=$(best_of "$nckit" moves "$program")
read -r rs_s rs_kb <<<"$rs_best"
read -r nc_s nc_kb <<<"$nc_best"

echo "| program | G1 blocks | rs274 -g time (s) | rs274 peak RSS (MB) | nckit moves time (s)" \
     "| nckit peak RSS (MB) | speed-up |"
echo "|---|---:|---:|---:|---:|---:|---:|"
LC_ALL=C awk -v blocks="$blocks" -v runs=$runs \
  -v rs_s="$rs_s" -v rs_kb="$rs_kb" -v nc_s="$nc_s" -v nc_kb="$nc_kb" 'BEGIN {
  speed = (nc_s > 0) ? sprintf("%.2fx", rs_s / nc_s) : "n/a (below timer resolution)"
  printf "| G41.1 lobed contour | %d | %.2f | %.1f | %.2f | %.1f | %s |\n",
         blocks, rs_s, rs_kb / 1024, nc_s, nc_kb / 1024, speed
  printf "\nbest of %d runs each\n", runs
}'
