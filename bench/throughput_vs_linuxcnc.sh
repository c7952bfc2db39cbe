#!/usr/bin/env bash
# Interpreter throughput, nckit against LinuxCNC: both read the same 1,000,000-line G1 program
# (a finishing raster over a surface, X Y with 3 decimals, Z with 4, a feed per row) and write
# their motions to /dev/null. Best wall time and peak RSS of 3 runs each, measured by GNU time.
#
# Usage: bench/throughput_vs_linuxcnc.sh [NCKIT_BINARY] [--signed4]   (default build/release/src/nckit)
#   --signed4: X Y Z all with 4 decimals and the surface centred on 0, so about half the values
#              are negative (the harder file of the mill-programs issue).
# Needs rs274 (linuxcnc-uspace) and /usr/bin/time (package time): scripts/deps.sh installs both.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
nckit=$repo/build/release/src/nckit
signed4=0
for arg in "$@"; do
  if [[ $arg == --signed4 ]]; then signed4=1; else nckit=$arg; fi
done
runs=3
rows=1000 cols=1000   # rows x cols = 1,000,000 G1 blocks

die() { echo "throughput_vs_linuxcnc: $*" >&2; exit 1; }
[[ -x $nckit ]] || die "nckit binary '$nckit' not found: build it (make build) or pass its path"
nckit=$(cd "$(dirname "$nckit")" && pwd)/$(basename "$nckit")
rs274=$(command -v rs274) || die "rs274 not on PATH: run scripts/deps.sh (installs linuxcnc-uspace)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: run scripts/deps.sh (installs time)"

work=$(mktemp -d -t nckit-throughput-XXXXXX)
trap 'rm -rf "$work"' EXIT
program=$work/raster_1m.ngc

# Zig-zag rows along X over z = -2 + 1.5 cos(x/18) sin(y/14), 0.2 mm apart, inside X Y 0..200.
LC_ALL=C awk -v rows=$rows -v cols=$cols -v signed4=$signed4 'BEGIN {
  fmt = signed4 ? "G1 X%.4f Y%.4f Z%.4f" : "G1 X%.3f Y%.3f Z%.4f"
  shift = signed4 ? 100.0 : 0.0
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
      x = i * 0.2 + (j % 7) * 0.0125 + (signed4 ? (j % 3) * 0.00017 : 0)
      z = -2 + 1.5 * cos(x / 18) * sin(y / 14) + (signed4 ? 2.0 : 0)
      if (k == 0) printf fmt " F%d\n", x - shift, y - shift, z, 1800 + (j % 5) * 100
      else        printf fmt "\n", x - shift, y - shift, z
    }
  }
  print "G0 Z25."
  print "M5"
  print "M30"
  print "%"
}' > "$program"
blocks=$(grep -c '^G1 ' "$program")

script_name=throughput_vs_linuxcnc
# shellcheck source=bench/best_of.sh
source "$repo/bench/best_of.sh"

label="G1 surface raster"
if ((signed4)); then label+=", X Y Z 4 decimals, signed"; fi
moves_vs_rs274 "$program" "$blocks" "$label"
