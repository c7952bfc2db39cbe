# Sourced by the side-by-side scripts. best_of CMD...: runs CMD $runs times inside $work (rs274
# rewrites its parameter file in its working folder), output to /dev/null; prints
# "best_seconds best_peak_kb" (wall time and peak resident memory from GNU time). $script_name
# names the caller in error messages.
best_of() {
  local best_s="" best_kb="" s kb i
  for ((i = 0; i < runs; i++)); do
    if ! (cd "$work" &&
          /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" >/dev/null 2>"$work/stderr.txt"); then
      echo "$script_name: '$*' failed:" >&2
      grep -v '^executing$' "$work/stderr.txt" | head -5 >&2
      exit 1
    fi
    read -r s kb < <(tail -n 1 "$work/time.txt")
    if [[ -z $best_s ]] || awk -v a="$s" -v b="$best_s" 'BEGIN { exit !(a < b) }'; then
      best_s=$s
    fi
    if [[ -z $best_kb ]] || ((kb < best_kb)); then best_kb=$kb; fi
  done
  echo "$best_s $best_kb"
}

# moves_vs_rs274 PROGRAM BLOCKS LABEL: the G1 throughput comparison. Untimed first, both rs274 -g
# and nckit moves must turn every one of the BLOCKS G1 blocks into a motion; then best_of times
# each, and one table row named LABEL (wall time, peak RSS, speed-up) is printed. Needs $rs274,
# $nckit, $work, $runs and die().
moves_vs_rs274() {
  local program=$1 blocks=$2 label=$3 rs_moves nc_moves rs_s rs_kb nc_s nc_kb
  rs_moves=$(cd "$work" && "$rs274" -g "$program" 2>/dev/null | grep -c 'STRAIGHT_FEED(\|ARC_FEED(') || true
  nc_moves=$("$nckit" moves "$program" | wc -l) || die "nckit moves failed on $program"
  ((rs_moves >= blocks)) || die "rs274 printed $rs_moves feeds for $blocks G1 blocks"
  ((nc_moves >= blocks)) || die "nckit printed $nc_moves lines for $blocks G1 blocks"

  read -r rs_s rs_kb <<<"$(best_of "$rs274" -g "$program")"
  read -r nc_s nc_kb <<<"$(best_of "$nckit" moves "$program")"

  echo "| program | G1 blocks | rs274 -g time (s) | rs274 peak RSS (MB) | nckit moves time (s)" \
       "| nckit peak RSS (MB) | speed-up |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
  LC_ALL=C awk -v blocks="$blocks" -v runs="$runs" -v label="$label" \
    -v rs_s="$rs_s" -v rs_kb="$rs_kb" -v nc_s="$nc_s" -v nc_kb="$nc_kb" 'BEGIN {
    speed = (nc_s > 0) ? sprintf("%.2fx", rs_s / nc_s) : "n/a (below timer resolution)"
    printf "| %s | %d | %.2f | %.1f | %.2f | %.1f | %s |\n",
           label, blocks, rs_s, rs_kb / 1024, nc_s, nc_kb / 1024, speed
    printf "\nbest of %d runs each; time ratio rs274/nckit = %s, memory ratio rs274/nckit = %.2f\n",
           runs, speed, (nc_kb > 0) ? rs_kb / nc_kb : 0
  }'
}
