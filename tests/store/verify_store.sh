#!/usr/bin/env bash
# make test's check of the result store (results/paper): recompute the cheapest units of
# every committed paper-profile file under the current code and compare them with the stored
# rows (--verify: numbers to 1e-9 relative, texts exactly; nothing is written).  A store that
# no longer matches its code fails the suite.  Files not yet in the store are named, not
# passed silently.
#
# With --recheck (by hand, after a change of the core that should not change the numbers):
# the same units are recomputed with --recheck instead, which re-stamps the rows of a file
# whose units agree with the check's record and recomputes the rows of one that differs.
# A file being written by a running study is locked: its recheck fails and says so.
#
# usage: verify_store.sh BUILD_DIR STORE_DIR [--recheck]
set -u
build=$1
store=$2
mode=${3:---verify}
case $mode in --verify|--recheck) ;; *) echo "verify_store.sh: unknown mode '$mode' (--verify or --recheck)" >&2; exit 2;; esac
failed=0 checked=0 absent=()
verify() {  # verify FILE PROGRAM ARGS...
  local file=$1 prog=$2
  shift 2
  if [ ! -f "$store/$file" ]; then absent+=("$file"); return; fi
  echo "== $file: $prog $* $mode"
  # The program's status, not the filter's: (an `if … | grep` would report the grep's).
  local log rc
  log=$("$build/$prog" "$@" --profile paper --out "$store/$file" "$mode" 2>&1)
  rc=$?
  grep '\[store\]\|rror' <<<"$log"
  if [ "$rc" -eq 0 ]; then checked=$((checked + 1)); else failed=$((failed + 1)); echo "   FAILED (exit $rc)"; fi
}
# The cheap units of each study: the coarse levels, which take seconds.
verify imoto_fig5_table1.tsv   imoto_fig5_table1 --levels 5,6,7
verify imoto_fig5_table1_seed2.tsv imoto_fig5_table1 --seed 2 --levels 5,6,7
verify imoto_fig5_table1_seed3.tsv imoto_fig5_table1 --seed 3 --levels 5,6,7
verify imoto_fig5_table1_plain.tsv imoto_fig5_table1 --jitter 0 --levels 5,6,7
verify thesis_table4_1.tsv     thesis_table4_1 --levels 5,6,7
verify thesis_table4_2.tsv     thesis_table4_2 --levels 5,6,7
verify thesis_table4_3.tsv     thesis_table4_3 --levels 5,6,7
verify thesis_table4_4.tsv     thesis_table4_4 --levels 5,6
for s in 2 3; do  # other jitter realizations, at the rate levels (seed bands)
  verify thesis_table4_1_seed$s.tsv thesis_table4_1 --seed $s --levels 5,6,7
  verify thesis_table4_3_seed$s.tsv thesis_table4_3 --seed $s --levels 5,6,7
  verify thesis_table4_4_seed$s.tsv thesis_table4_4 --seed $s --levels 5,6
done
for t in 5 6 7; do
  verify thesis_table4_$t.tsv     thesis_heat --table 4.$t --levels 5
  verify thesis_table4_${t}_h15.tsv thesis_heat --table 4.$t --h-rule h15 --levels 5
done
verify thesis_table4_7_dtexact.tsv thesis_heat --table 4.7 --dt-rule exact --levels 5
verify thesis_table4_5_cellvol.tsv thesis_heat --table 4.5 --volumes cell --levels 5
verify thesis_table4_6_cellvol.tsv thesis_heat --table 4.6 --volumes cell --levels 5
verify thesis_table4_7_cellvol.tsv thesis_heat --table 4.7 --volumes cell --levels 5
verify thesis_table4_7_dtexact_cellvol.tsv thesis_heat --table 4.7 --dt-rule exact --volumes cell --levels 5
verify thesis_stability.tsv    thesis_stability --levels 5
verify thesis_poisson_diagnostic.tsv thesis_poisson_diagnostic --levels 7 --weights quartic_polynomial \
  --variants seed1,plain,seed1_cell
[ ${#absent[@]} -gt 0 ] && echo "not in the store yet (nothing to check): ${absent[*]}"
stale=$(cat "$store"/*.tsv 2>/dev/null | grep -v '^#' | grep -c 'of code ' || true)
echo "store: $checked files agree with the current code, $failed differ; $stale rows carried over by a recorded re-check"
[ "$failed" -eq 0 ] && [ "$checked" -gt 0 ]
