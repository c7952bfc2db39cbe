#!/bin/sh
# Regenerates the notch golden files: sh tests/process/notch_golden/make_golden.sh NCKIT
# (run from the repository root; review the diff before committing).
set -u
nckit=$1
dir=tests/process/notch_golden
machine=examples/machines/notcher.toml
for program in examples/notch/conrod.nc $dir/multi.nc $dir/oblique.nc $dir/macro.nc; do
    name=$(basename "$program" .nc)
    "$nckit" notch "$program" --machine $machine -o $dir/$name.notched.nc.expected > $dir/$name.txt.expected
    "$nckit" notch "$program" --machine $machine --json > $dir/$name.json.expected
done
"$nckit" notch - --machine $machine -o $dir/stdin.notched.nc.expected < $dir/multi.nc > $dir/stdin.txt.expected
"$nckit" notch $dir/crossing.nc --machine $machine 2> $dir/crossing.err.expected
echo "crossing exit $?"
