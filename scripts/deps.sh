#!/usr/bin/env bash
# Installs the Debian packages nckit needs, by named group:
#   scripts/deps.sh               the build group (what `make run` needs)
#   scripts/deps.sh build test    the groups named
#   scripts/deps.sh all           every group
# Idempotent: apt is asked only for what is missing, so a second run costs a few dpkg look-ups.
# To add a package: put it in its group, after a comment line saying what uses it (a '#' starts a
# comment inside a group too).
set -euo pipefail

declare -A groups
# The compiler, CMake and the libraries nckit links; CMake's configure step also looks for
# nlohmann-json and GoogleTest (the release preset configures the tests with the rest).
groups[build]="
  build-essential cmake ninja-build
  libfmt-dev libcli11-dev libtomlplusplus-dev
  libeigen3-dev
  libmuparser-dev
  # dxflib reads the DXF outlines and motifs of nckit pattern.
  libdxflib-dev
  nlohmann-json3-dev
  libgtest-dev libgmock-dev
  # zlib compresses the data inside nckit report's HTML pages.
  zlib1g-dev
"
# The CLI and program tests (python3) and GNU time (peak memory in the streaming tests and
# bench/throughput_vs_linuxcnc.sh).
groups[test]="
  python3
  time
  # The report pages' browser test runs Debian's chromium headless (through puppeteer-core).
  chromium fonts-dejavu-core
  # The CTest format checks the layout of the sources with clang-format (14, as .clang-format expects).
  clang-format
  # The CTest bench_reference_scurve_line runs bench/jerk_reference.py, whose LPs need scipy (HiGHS).
  python3-scipy
"
# Google Benchmark for bench/.
groups[bench]="
  libbenchmark-dev
  # bench/jerk_reference.py (the jerk-limited reference of bench/scurve_reference.sh) solves its
  # LPs with scipy's linprog (HiGHS); it brings numpy along.
  python3-scipy
"
# LinuxCNC's rs274 interpreter: the reference the program tests and the throughput benchmark
# compare against. Large, so `make run` does not install it; `make test` and `make bench` do.
groups[linuxcnc]="
  linuxcnc-uspace
  # hal.h/rtapi.h and Makefile.modinc (the nckit_cam and nckit_servo HAL components, hal/);
  # interp_base.hh and canon.hh (the nckit interpreter plug-in, src/linuxcnc_interp/).
  linuxcnc-uspace-dev
  # boost/noncopyable.hpp, which interp_base.hh includes.
  libboost-dev
"
# clang with libFuzzer and the sanitizer runtimes: `make fuzz` and CI's fuzzing.
groups[fuzz]="
  clang
  libclang-rt-14-dev
"

wanted=("$@")
if ((${#wanted[@]} == 0)); then wanted=(build); fi
if [[ ${wanted[0]} == all ]]; then wanted=(build test bench linuxcnc fuzz); fi

missing=()
for group in "${wanted[@]}"; do
  if [[ -z ${groups[$group]+set} ]]; then
    echo "deps: unknown group '$group' (groups: ${!groups[*]} all)" >&2
    exit 2
  fi
  # Comments inside a group end at the line's end; what is left are package names.
  for p in $(sed 's/#.*//' <<<"${groups[$group]}"); do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
done

# node and npm bundle the report viewer (web/) at build time; a machine that has node from
# elsewhere keeps it.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then missing+=(nodejs npm); fi

if ((${#missing[@]} > 0)); then
  echo "deps: installing ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update
  # apt's own progress: LinuxCNC alone is a few hundred MB.
  "${sudo_cmd[@]}" apt-get install -y --no-install-recommends -o Dpkg::Progress-Fancy=1 "${missing[@]}"
fi

# The viewer's npm packages, exactly as web/package-lock.json pins them: three and uplot (in the
# page), esbuild (bundles it at build time), puppeteer-core and pngjs (the browser test drives
# Debian's chromium; puppeteer-core never downloads a browser, and PUPPETEER_SKIP_DOWNLOAD makes
# sure nothing else does). Skipped when node_modules matches the lockfile already.
web="$(cd "$(dirname "${BASH_SOURCE[0]}")/../web" && pwd)"
stamp="$web/node_modules/.package-lock.json"
if [[ ! -f "$stamp" || "$web/package-lock.json" -nt "$stamp" ]]; then
  echo "deps: npm ci in web/"
  (cd "$web" && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi
