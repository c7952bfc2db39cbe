#!/usr/bin/env bash
# Macro engine speed, nckit against LinuxCNC: 200,000 iterations of a WHILE loop that accumulates
# #100 = #100 + SIN[#1] * COS[#1], with one G1 after every 1,000 iterations (200 moves in all),
# so that the time is the macro interpreter's, not motion output. nckit runs it as Fanuc Custom
# Macro B (WHILE [..] DO1 / END1), rs274 as the equivalent LinuxCNC O-word loop (o100 while ..
# o100 endwhile), both with their motions going to /dev/null. Best wall time and peak RSS of 3
# runs each, measured by GNU time.
#
# Usage: bench/macro_vs_linuxcnc.sh [NCKIT_BINARY]   (default build/release/src/nckit)
# Needs rs274 (linuxcnc-uspace) and /usr/bin/time (package time): scripts/deps.sh installs both.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
nckit=${1:-$repo/build/release/src/nckit}
runs=3
outer=200 inner=1000   # outer x inner = 200,000 iterations, one G1 per outer pass
# nckit stops a program after 10,000,000 blocks run in loops and calls (a runaway guard); this
# one runs about 1,000,000 (WHILE, three assignments and END per iteration): a generous budget.
max_blocks=100000000

die() { echo "macro_vs_linuxcnc: $*" >&2; exit 1; }
[[ -x $nckit ]] || die "nckit binary '$nckit' not found: build it (make build) or pass its path"
nckit=$(cd "$(dirname "$nckit")" && pwd)/$(basename "$nckit")
rs274=$(command -v rs274) || die "rs274 not on PATH: run scripts/deps.sh (installs linuxcnc-uspace)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: run scripts/deps.sh (installs time)"

work=$(mktemp -d -t nckit-macro-XXXXXX)
trap 'rm -rf "$work"' EXIT
fanuc=$work/trig_loop.nc
linuxcnc=$work/trig_loop.ngc
iterations=$((outer * inner))

# The same loop twice. Angles are degrees in both dialects; X = iterations so far / 1000 and
# Y = the running sum (it stays within about +-30), inside the default mill's +-500 mm travel.
cat > "$fanuc" <<EOF
%
O0100 (MACRO B: $iterations ITERATIONS OF A WHILE LOOP WITH TRIG, A G1 EVERY $inner)
G21 G17 G90 G94
G0 X0 Y0 Z5.
#1 = 0
#100 = 0
WHILE [#1 LT $iterations] DO1
  #3 = 0
  WHILE [#3 LT $inner] DO2
    #100 = #100 + SIN[#1] * COS[#1]
    #1 = #1 + 1
    #3 = #3 + 1
  END2
  G1 X[#1 / 1000] Y#100 F1000.
END1
G0 Z25.
M30
%
EOF
cat > "$linuxcnc" <<EOF
%
(LinuxCNC O-words: $iterations iterations of a while loop with trig, a G1 every $inner)
G21 G17 G90 G94
G0 X0 Y0 Z5.
#1 = 0
#100 = 0
o100 while [#1 LT $iterations]
  #3 = 0
  o101 while [#3 LT $inner]
    #100 = [#100 + SIN[#1] * COS[#1]]
    #1 = [#1 + 1]
    #3 = [#3 + 1]
  o101 endwhile
  G1 X[#1 / 1000] Y#100 F1000.
o100 endwhile
G0 Z25.
M2
%
EOF

script_name=macro_vs_linuxcnc
# shellcheck source=bench/best_of.sh
source "$repo/bench/best_of.sh"

# Untimed sanity check: both must make the $outer feeds and end at the same X Y (the running
# sum to 0.001 mm: nckit rounds a variable in an address to the least input increment).
rs_out=$(cd "$work" && "$rs274" -g "$linuxcnc" 2>/dev/null | grep 'STRAIGHT_FEED(') || true
nc_out=$("$nckit" moves "$fanuc" --max-blocks $max_blocks | grep '^G1 ') ||
  die "nckit moves failed on $fanuc"
rs_feeds=$(grep -c . <<<"$rs_out")
nc_feeds=$(grep -c . <<<"$nc_out")
((rs_feeds == outer)) || die "rs274 printed $rs_feeds feeds, expected $outer"
((nc_feeds == outer)) || die "nckit printed $nc_feeds feeds, expected $outer"
rs_end=$(tail -n 1 <<<"$rs_out" | sed -E 's/.*STRAIGHT_FEED\(([^,]+), *([^,]+),.*/\1 \2/')
nc_end=$(tail -n 1 <<<"$nc_out" | sed -E 's/^G1 X([^ ]+) Y([^ ]+) .*/\1 \2/')
LC_ALL=C awk -v a="$rs_end" -v b="$nc_end" 'BEGIN {
  split(a, r, " "); split(b, n, " ")
  dx = r[1] - n[1]; dy = r[2] - n[2]
  exit !(dx < 0.001 && dx > -0.001 && dy < 0.001 && dy > -0.001)
}' || die "last feed ends at X Y $rs_end in rs274 but $nc_end in nckit"

rs_best=$(best_of "$rs274" -g "$linuxcnc")
nc_best=$(best_of "$nckit" moves "$fanuc" --max-blocks $max_blocks)
read -r rs_s rs_kb <<<"$rs_best"
read -r nc_s nc_kb <<<"$nc_best"

echo "| program | loop iterations | rs274 -g time (s) | rs274 peak RSS (MB) | nckit moves time (s)" \
     "| nckit peak RSS (MB) | speed-up |"
echo "|---|---:|---:|---:|---:|---:|---:|"
LC_ALL=C awk -v iterations="$iterations" -v runs=$runs \
  -v rs_s="$rs_s" -v rs_kb="$rs_kb" -v nc_s="$nc_s" -v nc_kb="$nc_kb" 'BEGIN {
  speed = (nc_s > 0) ? sprintf("%.2fx", rs_s / nc_s) : "n/a (below timer resolution)"
  printf "| WHILE loop with SIN COS | %d | %.2f | %.1f | %.2f | %.1f | %s |\n",
         iterations, rs_s, rs_kb / 1024, nc_s, nc_kb / 1024, speed
  printf "\nbest of %d runs each; time ratio rs274/nckit = %s\n", runs, speed
}'
