#!/bin/bash
# The core's layers, checked from its includes: a file under src/gpm/<layer>/ may include
# its own layer, error.hpp, and the numerics layers below it; io includes only io.  The
# numerics never include io, so that the numbers cannot depend on how options are parsed or
# files are written.  studies/ is four rooms, each a layer of its own (studies/<room>/):
#   define  the studies as the package defines them (catalog, set-ups, units, prices):
#           numerics, io and define only;
#   run     running units and keeping the store: also define;
#   plan    pricing a profile and comparing it with the runs: also define and run;
#   judge   rates, verdicts and their reasons from the store: define, never run or plan
#           (a judgement reads stored rows; it does not run or price anything).
# A file directly under studies/ belongs to no room and is a violation.
#   bash check_layers.sh SRC_GPM_DIR      (exit 1 and one line per violation)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
root=${1:?usage: check_layers.sh SRC_GPM_DIR}
[ -d "$root" ] || { echo "check_layers: no directory '$root'" >&2; exit 2; }
# Numerics, lowest first.  A layer may include any layer listed before it.
order=(geometry weights kernel operators solvers theory)
rank() { local i; for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
numeric() { [ "$(rank "$1")" -ge 0 ]; }
allowed() {  # allowed FROM TO
  local from=$1 to=$2
  [ "$from" = "$to" ] && return 0
  case $from in
    studies/define) numeric "$to" || [ "$to" = io ]; return ;;
    studies/run) numeric "$to" || [ "$to" = io ] || [ "$to" = studies/define ]; return ;;
    studies/plan) numeric "$to" || [ "$to" = io ] || [ "$to" = studies/define ] || [ "$to" = studies/run ]; return ;;
    studies/judge) numeric "$to" || [ "$to" = io ] || [ "$to" = studies/define ]; return ;;
    studies) return 1 ;;
  esac
  [ "$from" = io ] && return 1
  [ "$to" = io ] || [ "${to%%/*}" = studies ] && return 1
  local rf rt; rf=$(rank "$from"); rt=$(rank "$to")
  [ "$rf" -ge 0 ] && [ "$rt" -ge 0 ] && [ "$rt" -lt "$rf" ]
}
bad=0 files=0
while IFS= read -r f; do
  rel=${f#"$root"/}
  case $rel in studies/*/*) from=${rel%/*} ;; */*) from=${rel%%/*} ;; *) from=root ;; esac
  files=$((files + 1))
  while IFS= read -r line; do
    inc=${line#*\"gpm/}; inc=${inc%%\"*}
    case $inc in studies/*/*) to=${inc%/*} ;; */*) to=${inc%%/*} ;; *) to=root ;; esac
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
