#!/usr/bin/env bash
# nckit report on a 1,000,000-move program: the page's size, the time and memory nckit needs to
# write it, and the time until the page is interactive in Debian's chromium (headless, through
# puppeteer-core; see web/test/measure_load.mjs). The issue asks for <= 30 MB and <= 5 s.
# Usage: bench/report_large.sh [NCKIT] [ROWS COLS]   (default build/release/src/nckit, 1000 x 1000)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
nckit=${1:-$here/../build/release/src/nckit}
rows=${2:-1000}
cols=${3:-1000}
die() { echo "report_large: $*" >&2; exit 1; }
[[ -x $nckit ]] || die "nckit binary '$nckit' not found: build it (make build) or pass its path"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: run scripts/deps.sh (installs time)"

work=$(mktemp -d -t nckit-report-XXXXXX)
trap 'rm -rf "$work"' EXIT
program=$work/raster.ngc

# The raster of throughput_vs_linuxcnc.sh: zig-zag rows along X over a smooth surface.
LC_ALL=C awk -v rows=$rows -v cols=$cols 'BEGIN {
  print "%"
  print "(finishing raster: " rows " rows of " cols " G1 blocks)"
  print "G21 G17 G90 G94"
  print "G64 P0.01"
  print "S6000 M3"
  print "G0 X0. Y0. Z5."
  for (j = 0; j < rows; j++) {
    y = j * 0.2
    for (k = 0; k < cols; k++) {
      i = (j % 2 == 0) ? k : cols - 1 - k
      x = i * 0.2 + (j % 7) * 0.0125
      z = -2 + 1.5 * cos(x / 18) * sin(y / 14)
      if (k == 0) printf "G1 X%.3f Y%.3f Z%.4f F%d\n", x, y, z, 1800 + (j % 5) * 100
      else        printf "G1 X%.3f Y%.3f Z%.4f\n", x, y, z
    }
  }
  print "G0 Z25."
  print "M5"
  print "M30"
}' > "$program"

echo "program: $(wc -l < "$program") lines, $(du -m "$program" | cut -f1) MB"
/usr/bin/time -f "%e %M" -o "$work/time" "$nckit" report "$program" -o "$work/page.html"
read -r wall_s peak_kb < "$work/time"
size=$(stat -c %s "$work/page.html")
echo "nckit report: ${wall_s} s, peak ${peak_kb} KB; page $(awk -v s="$size" 'BEGIN { printf "%.2f", s / 1e6 }') MB"
node "$here/../web/test/measure_load.mjs" "$work/page.html" 3
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
