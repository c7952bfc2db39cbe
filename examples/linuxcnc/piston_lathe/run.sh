#!/usr/bin/env bash
# Turns the example piston on this folder's LinuxCNC sim lathe (piston_lathe.hal) and prints
# its profile error beside nckit's simulated figure for the same job.
#   run.sh [NCKIT]    (default: build/release/src/nckit of this checkout)
#   LEARNING=1 run.sh  learning across revolutions on as well as feedforward
# Needs LinuxCNC (scripts/deps.sh) and the modules where loadrt finds them (cmake --build
# build/release --target hal-install). One LinuxCNC instance per machine: wrap it in
# `flock /tmp/nckit-linuxcnc.lock` where others may run one.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
nckit=${1:-$here/../../../build/release/src/nckit}
work=$(mktemp -d /tmp/nckit_piston_lathe.XXXXXX)
chmod 1777 "$work"
"$nckit" piston "$here/piston.toml" --cam-table "$work/piston_cam.csv" --json > "$work/nckit.json"
chmod 644 "$work/piston_cam.csv"
export PISTON_CAM="$work/piston_cam.csv" PISTON_SAMPLES="$work/samples.txt" PISTON_LEARNING="${LEARNING:-0}"
if [[ $(id -u) -eq 0 ]]; then
  # rtapi_app as root needs a fallback user and a socket that user can reach.
  mkdir -p "$work/rtapi" && chmod 1777 "$work/rtapi"
  export RTAPI_UID=65534 RTAPI_FIFO_PATH="$work/rtapi/rtapi_fifo"
fi
script -qec "halrun -f $here/piston_lathe.hal" /dev/null > "$work/halrun.log" 2>&1 || {
  cat "$work/halrun.log" >&2
  exit 1
}
python3 "$here/profile_error.py" "$work/samples.txt" "$work/nckit.json" "${LEARNING:-0}"
echo "samples: $work/samples.txt"
