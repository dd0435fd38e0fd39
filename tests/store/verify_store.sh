#!/usr/bin/env bash
# make test's check of the result store (results/paper), on the store or on any copy of it.
# For every file the store is expected to hold (the list below):
#   1. census: the file is there and holds every unit of its levels (nothing is computed);
#      reading it already refuses a row whose seal does not match its cells, a short or long
#      row, a duplicate, CRLF line endings or a byte-order mark, other parameters;
#   2. verify: its cheapest units are recomputed under the current code and compared with the
#      stored rows (numbers to 1e-9 relative, texts exactly; a non-finite number never agrees);
#   3. where its finer rows were computed matrix-free, the coarse units again by that path
#      (errors to 1e-9 relative: the storage path the fine rows took is exercised too).
# A file missing from the store fails, as does any check above.
#
# With --recheck (by hand, after a change of the core that should not change the numbers):
# step 2 runs with --recheck instead, which re-stamps the rows of a file whose units agree
# and recomputes the rows of one that differs.  A file being written by a running study is
# locked: its recheck fails and says so.
#
# usage: verify_store.sh BUILD_DIR STORE_DIR [--verify|--recheck] [FILE...]
#   FILE...: check only these files of the list (the others are not required).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
usage="usage: verify_store.sh BUILD_DIR STORE_DIR [--verify|--recheck] [FILE...]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
build=$1
store=$2
[ -x "$build/gpm" ] || { echo "verify_store.sh: $build/gpm not found (BUILD_DIR: a build folder); $usage" >&2; exit 2; }
[ -d "$store" ] || { echo "verify_store.sh: $store is not a directory; $usage" >&2; exit 2; }
mode=${3:---verify}
case $mode in --verify|--recheck) ;; *) echo "verify_store.sh: unknown mode '$mode' (--verify or --recheck)" >&2; exit 2;; esac
shift $(( $# < 3 ? $# : 3 ))
only=" $* "
failed=0 checked=0 missing=() seen_files=()

# Rows are keyed by (h rule, weight, level, theta, propagator), the columns a file has of them.
row_keys='BEGIN { keys[1] = "h_rule"; keys[2] = "weight"; keys[3] = "level"; keys[4] = "theta"; keys[5] = "propagator" }
  /^#/ { next }
  !seen[FILENAME]++ { for (i = 1; i <= NF; i++) col[FILENAME, $i] = i; next }
  { key = ""; for (k = 1; k <= 5; k++) if ((FILENAME, keys[k]) in col) key = key "|" $col[FILENAME, keys[k]] }'
# same_keys A B: every row of A has a row of B with its key.
same_keys() {
  awk -F'\t' "$row_keys"' FILENAME == ARGV[1] { want[key]; next } { have[key] }
    END { for (k in want) if (!(k in have)) exit 1 }' "$1" "$2"
}
# compare_errors LABEL A B: A's rel_error against B's row of the same key, to 1e-9 relative.
compare_errors() {
  awk -F'\t' -v label="$1" "$row_keys"'
    { e = $col[FILENAME, "rel_error"] }
    FILENAME == ARGV[1] { mf[key] = e; next }
    (key in mf) { n++; d = mf[key] - e; if (d < 0) d = -d; s = (e < 0 ? -e : e); r = s > 0 ? d / s : d
                  if (r > worst) worst = r }
    END { printf "[store] matrix-free path of %s: %d coarse rows, max relative difference of rel_error %.3g", label, n, worst
          if (n == 0 || worst > 1e-9) { print ": DIFFERS"; exit 1 } print ": agree" }' "$2" "$3"
}

# check FILE "CENSUS OPTIONS" "VERIFY OPTIONS" PROGRAM ARGS...
#   CENSUS OPTIONS: empty for the profile's paper levels, or e.g. "--levels 5,6,7,10,11";
#   VERIFY OPTIONS: the cheap units to recompute, e.g. "--levels 5,6,7".
check() {
  local file=$1 census=$2 coarse=$3 prog=$4
  shift 4
  [ "$only" != "  " ] && [[ "$only" != *" $file "* ]] && return
  seen_files+=("$file")
  if [ ! -f "$store/$file" ]; then missing+=("$file"); failed=$((failed + 1)); return; fi
  echo "== $file: $prog $*"
  local log rc=0 step
  # The program's status, not a filter's (an `if … | grep` would report the grep's).
  # shellcheck disable=SC2086  # the options are words
  log=$("$build/$prog" "$@" $census --profile paper --out "$store/$file" --census 2>&1) || rc=$?
  step=census
  if [ "$rc" -eq 0 ]; then
    # shellcheck disable=SC2086
    log+=$'\n'$("$build/$prog" "$@" $coarse --profile paper --out "$store/$file" "$mode" 2>&1) || rc=$?
    step=${mode#--}
  fi
  # 3. the other storage path: a file whose fine rows were computed matrix-free has its
  #    coarse units computed matrix-free too (into a scratch file), by the propagator those
  #    fine rows used, and their errors compared to 1e-9 relative with the stored rows of that
  #    propagator; where the coarse rows were made by another propagator (Table 4.5 steps its
  #    coarse levels and advances 2^-10 by Krylov), with a fresh assembled run of the same
  #    propagator.  So the path the fine rows took is exercised by the check, and only that
  #    one (a matrix-free stepped run of thousands of steps would cost the check 20 minutes).
  if [ "$rc" -eq 0 ] && grep -q $'\tmatrix_free\t' "$store/$file"; then
    local scratch props p ref; scratch=$(mktemp -d)
    props=$(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) { if ($i == "propagator") c = i; if ($i == "storage") s = i }; next }
                        $s == "matrix_free" { print (c ? $c : "none") }' "$store/$file" | sort -u)
    for p in $props; do
      local how=(); [ "$p" != none ] && how=(--propagator "$p")
      # shellcheck disable=SC2086
      log+=$'\n'$("$build/$prog" "$@" $coarse --profile paper --storage matrix_free "${how[@]}" --out "$scratch/mf_$p.tsv" 2>&1) || rc=$?
      ref=$store/$file
      if [ "$rc" -eq 0 ] && [ "$p" != none ] && ! same_keys "$scratch/mf_$p.tsv" "$ref"; then
        ref=$scratch/assembled_$p.tsv
        # shellcheck disable=SC2086
        log+=$'\n'$("$build/$prog" "$@" $coarse --profile paper --storage assembled "${how[@]}" --out "$ref" 2>&1) || rc=$?
      fi
      step=matrix_free
      [ "$rc" -eq 0 ] || break
      log+=$'\n'$(compare_errors "$file ($p, against ${ref##*/})" "$scratch/mf_$p.tsv" "$ref") || rc=$?
    done
    rm -rf "$scratch"
  fi
  grep '\[store\]\|rror' <<<"$log"
  if [ "$rc" -eq 0 ]; then checked=$((checked + 1)); else failed=$((failed + 1)); echo "   FAILED ($step, exit $rc)"; fi
}

# The store's files, from the study registry (src/gpm/studies/define/registry.cpp, each study's
# store_files): program and arguments, the units each must hold (census; empty: the profile's
# paper levels) and the cheap units recomputed.
listing=$("$build/gpm" study --store-rows) || { echo "verify_store.sh: gpm study --store-rows failed" >&2; exit 2; }
# (An empty cell is written "-": read would merge two tabs.)
while IFS=$'\t' read -r _study file program args census coarse _slice; do
  [ "$args" = - ] && args=""
  [ "$census" = - ] && census=""
  [ "$coarse" = - ] && coarse=""
  # shellcheck disable=SC2086  # the arguments are words
  check "$file.tsv" "$census" "$coarse" "$program" $args
done <<<"$listing"

[ ${#missing[@]} -gt 0 ] && echo "MISSING from the store: ${missing[*]}"
# A full check: every data file in the store is one of the above (a registered study's), so
# sealed and checked; anything else fails.
if [ "$only" = "  " ]; then
  for f in "$store"/*.tsv; do
    [ -e "$f" ] || continue
    case " ${seen_files[*]} " in *" $(basename "$f") "*) ;; *)
      echo "NOT IN THE REGISTRY: $(basename "$f") (the store holds only sealed files of the registered studies)"
      failed=$((failed + 1)) ;;
    esac
  done
fi
stale=$(cat "$store"/*.tsv 2>/dev/null | grep -v '^#' | grep -c 'of code ' || true)
echo "store: $checked files pass the census and agree with the current code, $failed fail; $stale rows carried over by a recorded re-check"
[ "$failed" -eq 0 ] && [ "$checked" -gt 0 ]
