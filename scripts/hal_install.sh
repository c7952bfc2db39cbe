#!/usr/bin/env bash
# Puts nckit's HAL modules where LinuxCNC's `loadrt` looks for them: it loads only from its
# module folder (/usr/lib/linuxcnc/modules on Debian), by name.
#   scripts/hal_install.sh MODULE_DIR MODULE.so...
# Where the folder is writable (root, as CI runs) the modules are copied. Otherwise they are
# linked there with sudo, once: the links point at the build, so later builds are loaded without
# root. A module already in place (the same file, or a link to it) is left alone.
set -euo pipefail
dir=$1
shift
for module in "$@"; do
  source_path=$(readlink -f "$module")
  target="$dir/$(basename "$module")"
  if [[ -e "$target" ]] && [[ "$(readlink -f "$target")" == "$source_path" ]]; then continue; fi
  if [[ -f "$target" ]] && cmp -s "$source_path" "$target"; then continue; fi
  if [[ -w "$dir" ]]; then
    install -m 644 "$source_path" "$target.new"
    mv -f "$target.new" "$target"
  elif sudo -n true 2>/dev/null; then
    sudo ln -sfn "$source_path" "$target"
  else
    echo "$target:0:0: error: LinuxCNC loads modules only from $dir, which this user cannot write;" \
         "run once: sudo bash scripts/hal_install.sh $dir $*" >&2
    exit 2
  fi
done
