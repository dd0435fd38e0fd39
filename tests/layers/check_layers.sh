#!/bin/bash
# The core's layers, checked from its includes: a file under src/gpm/<layer>/ may include
# its own layer, error.hpp, and the numerics layers below it; io includes only io; studies
# may include everything.  The numerics never include io, so that the numbers cannot depend
# on how options are parsed or files are written.
#   bash check_layers.sh SRC_GPM_DIR      (exit 1 and one line per violation)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
root=${1:?usage: check_layers.sh SRC_GPM_DIR}
[ -d "$root" ] || { echo "check_layers: no directory '$root'" >&2; exit 2; }
# Numerics, lowest first.  A layer may include any layer listed before it.
order=(geometry weights kernel operators solvers theory)
rank() { local i; for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
allowed() {  # allowed FROM TO
  local from=$1 to=$2
  [ "$from" = "$to" ] && return 0
  [ "$from" = studies ] && return 0
  [ "$from" = io ] && return 1
  [ "$to" = io ] || [ "$to" = studies ] && return 1
  local rf rt; rf=$(rank "$from"); rt=$(rank "$to")
  [ "$rf" -ge 0 ] && [ "$rt" -ge 0 ] && [ "$rt" -lt "$rf" ]
}
bad=0 files=0
while IFS= read -r f; do
  rel=${f#"$root"/}
  case $rel in */*) from=${rel%%/*} ;; *) from=root ;; esac
  files=$((files + 1))
  while IFS= read -r line; do
    inc=${line#*\"gpm/}; inc=${inc%%\"*}
    case $inc in */*) to=${inc%%/*} ;; *) to=root ;; esac
    [ "$to" = root ] && continue               # error.hpp: every layer throws its errors
    if [ "$from" = root ] || ! allowed "$from" "$to"; then
      echo "layer violation: $rel ($from) includes gpm/$inc ($to)"
      bad=$((bad + 1))
    fi
  done < <(grep -h '^#include "gpm/' "$f")
done < <(find "$root" -name '*.hpp' -o -name '*.cpp' | sort)
[ "$files" -gt 0 ] || { echo "check_layers: no sources under '$root'" >&2; exit 2; }
echo "check_layers: $files files, $bad violations"
[ "$bad" -eq 0 ]
