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
