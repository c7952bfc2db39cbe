#!/usr/bin/env bash
# Installs every Debian package nckit needs to build, test and benchmark. Idempotent: it asks
# apt only for what is missing, so a second run costs a few dpkg look-ups.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libeigen3-dev libmuparser-dev libcpp-httplib-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3
  # dxflib reads the DXF outlines and motifs of nckit pattern.
  libdxflib-dev
  # GNU time: wall time and peak memory in bench/throughput_vs_linuxcnc.sh.
  time
  # LinuxCNC's rs274 interpreter is the reference the program tests compare against.
  linuxcnc-uspace
  # hal.h/rtapi.h and Makefile.modinc (the nckit_cam and nckit_servo HAL components, hal/);
  # interp_base.hh and canon.hh (the nckit interpreter plug-in, src/linuxcnc_interp/).
  linuxcnc-uspace-dev
  # boost/noncopyable.hpp, which interp_base.hh includes.
  libboost-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
