#!/usr/bin/env bash
# The CTest `format`: every C++ source of the tree is laid out as .clang-format says, so a change
# never mixes layout with meaning. Lists each file clang-format would change and how to fix it.
set -euo pipefail
root=${1:?usage: check_format.sh SOURCE_ROOT}
cd "$root"
command -v clang-format >/dev/null || { echo "format: clang-format is missing (scripts/deps.sh test)" >&2; exit 1; }
mapfile -t files < <(find src include tests bench fuzz hal examples \
  \( -name node_modules -o -name build \) -prune -o \
  -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) -print | sort)
# One clang-format run over every file; it names each offending file in its warnings.
mapfile -t bad < <(clang-format --dry-run "${files[@]}" 2>&1 | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: warning: code should be clang-formatted.*/\1/p' | sort -u)
if ((${#bad[@]} > 0)); then
  printf 'format: %s is not laid out as .clang-format says\n' "${bad[@]}" >&2
  echo "format: fix with: clang-format -i ${bad[*]}" >&2
  exit 1
fi
echo "format: ${#files[@]} files laid out as .clang-format says"
