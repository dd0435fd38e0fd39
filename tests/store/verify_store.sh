#!/usr/bin/env bash
# make test's check of the result store (results/paper), on the store or on any copy of it.
# For every file the store is expected to hold (the list below):
#   1. census: the file is there and holds every unit of its levels (nothing is computed);
#      reading it already refuses a row whose seal does not match its cells, a short or long
#      row, a duplicate, CRLF line endings or a byte-order mark, other parameters;
#   2. verify: its cheapest units are recomputed under the current code and compared with the
#      stored rows (numbers to 1e-9 relative, texts exactly; a non-finite number never agrees).
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
build=$1
store=$2
mode=${3:---verify}
case $mode in --verify|--recheck) ;; *) echo "verify_store.sh: unknown mode '$mode' (--verify or --recheck)" >&2; exit 2;; esac
shift $(( $# < 3 ? $# : 3 ))
only=" $* "
failed=0 checked=0 missing=()

# check FILE "CENSUS OPTIONS" "VERIFY OPTIONS" PROGRAM ARGS...
#   CENSUS OPTIONS: empty for the profile's paper levels, or e.g. "--levels 5,6,7,10,11";
#   VERIFY OPTIONS: the cheap units to recompute, e.g. "--levels 5,6,7".
check() {
  local file=$1 census=$2 coarse=$3 prog=$4
  shift 4
  [ "$only" != "  " ] && [[ "$only" != *" $file "* ]] && return
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
  grep '\[store\]\|rror' <<<"$log"
  if [ "$rc" -eq 0 ]; then checked=$((checked + 1)); else failed=$((failed + 1)); echo "   FAILED ($step, exit $rc)"; fi
}

# The store's files: census levels (paper profile unless named), coarse units to recompute.
coarse="--levels 5,6,7"
check imoto_fig5_table1.tsv       "" "$coarse" imoto_fig5_table1
check imoto_fig5_table1_seed2.tsv "" "$coarse" imoto_fig5_table1 --seed 2
check imoto_fig5_table1_seed3.tsv "" "$coarse" imoto_fig5_table1 --seed 3
for s in 4 5; do  # the rate levels 2^-11/2^-12 and the coarse ones, for the seed bands
  check imoto_fig5_table1_seed$s.tsv "--levels 5,6,7,11,12" "$coarse" imoto_fig5_table1 --seed $s
done
check imoto_fig5_table1_plain.tsv "" "$coarse" imoto_fig5_table1 --jitter 0
check imoto_fig5_table1_cellvol.tsv "" "$coarse" imoto_fig5_table1 --volumes cell
for t in 1 2 3; do check thesis_table4_$t.tsv "" "$coarse" thesis_table4_$t; done
check thesis_table4_4.tsv "" "--levels 5,6" thesis_table4_4
check thesis_table4_4_cellvol.tsv "" "--levels 5,6" thesis_table4_4 --volumes cell
for s in 2 3; do  # other jitter realizations: the coarse levels and the rate levels (seed bands)
  check thesis_table4_1_seed$s.tsv "--levels 5,6,7,10,11" "$coarse" thesis_table4_1 --seed $s
  check thesis_table4_3_seed$s.tsv "--levels 5,6,7,10,11" "$coarse" thesis_table4_3 --seed $s
  check thesis_table4_4_seed$s.tsv "--levels 5,6,8,9" "--levels 5,6" thesis_table4_4 --seed $s
done
# The heat tables, one file per reading of the set-up (tables/store_lib.sh's heat_file).
heat() {  # heat TABLE FILE-SUFFIX "CENSUS OPTIONS" THESIS_HEAT-ARGS...
  local t=$1 suffix=$2 census=$3
  shift 3
  check thesis_table4_$t$suffix.tsv "$census" "--levels 5" thesis_heat --table 4.$t "$@"
}
# The catalog's paper levels for h10 and h15; the other readings at 2^-5 and the rate levels.
for t in 5 6 7; do
  heat $t "" ""
  heat $t _h15 "" --h-rule h15
done
heat 5 _cellvol "--levels 5,7,8" --volumes cell
heat 6 _cellvol "--levels 5,8,9" --volumes cell
heat 7 _cellvol "--levels 5,8,9" --volumes cell
heat 7 _dtexact "--levels 5,8,9" --dt-rule exact
heat 7 _dtexact_cellvol "--levels 5,6,7,8,9" --dt-rule exact --volumes cell
# Table 4.6's theta = 0 fingerprint under every reading (setup_identification), 2^-5 ... 2^-9.
heat 6 _dtexact "--levels 5,6,7,8,9" --thetas 0 --dt-rule exact
heat 6 _dtexact_cellvol "--levels 5,6,7,8,9" --thetas 0 --dt-rule exact --volumes cell
# Tables 4.6 and 4.7 under h15, every theta at the documents' levels 2^-5 ... 2^-9, with the
# other volumes and time step (the reading matrix, issue 25); 2^-5 for the cheap re-check.
heat 6 _h15 "--levels 5,8,9" --h-rule h15
heat 6 _h15_cellvol "--levels 5,6,7,8,9" --h-rule h15 --volumes cell
heat 6 _h15_dtexact "--levels 5,6,7,8,9" --h-rule h15 --dt-rule exact
heat 7 _h15_cellvol "--levels 5,6,7,8,9" --h-rule h15 --volumes cell
heat 7 _h15_dtexact "--levels 5,6,7,8,9" --h-rule h15 --dt-rule exact
# The identified reading (h15, V_i = dx^2, dt = dt0): every theta at the documents' levels.
heat 6 _h15_dtexact_cellvol "--levels 5,6,7,8,9" --h-rule h15 --dt-rule exact --volumes cell
heat 5 _h15_dtexact_cellvol "--levels 4,5,6,7,8" --h-rule h15 --dt-rule exact --volumes cell
heat 7 _h15_dtexact_cellvol "--levels 5,8,9" --h-rule h15 --dt-rule exact --volumes cell
check thesis_poisson_diagnostic.tsv "--levels 7,8,9 --variants seed1,plain,seed1_cell,plain_cell" \
  "--levels 7 --weights quartic_polynomial --variants seed1,plain,seed1_cell" thesis_poisson_diagnostic

[ ${#missing[@]} -gt 0 ] && echo "MISSING from the store: ${missing[*]}"
stale=$(cat "$store"/*.tsv 2>/dev/null | grep -v '^#' | grep -c 'of code ' || true)
echo "store: $checked files pass the census and agree with the current code, $failed fail; $stale rows carried over by a recorded re-check"
[ "$failed" -eq 0 ] && [ "$checked" -gt 0 ]
