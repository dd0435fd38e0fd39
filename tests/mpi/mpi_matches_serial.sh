#!/usr/bin/env bash
# mpirun -np 2 against one process: every catalog study kind (fused truncation passes with
# and without Voronoi volumes, the Poisson problem, the heat problem) at small levels; the
# data rows must be identical, the columns that measure the run (time, memory, the machine
# line) aside.  Also: a rerun on 2 ranks reuses every unit, and 2 ranks refuse --verify
# (exit non-zero with the message).
#   mpi_matches_serial.sh BUILD_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/../.." && pwd)/tables/census_lib.sh"
build=$1
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mpi=(mpirun --allow-run-as-root --oversubscribe -np 2)
export OMP_NUM_THREADS=1
# rows FILE: the data rows by named columns, without those that measure the run.
rows() { data_rows "$1" '(_s|seconds|s_per_step|made_on)$|rss'; }
fail=0
check() {  # check NAME PROGRAM ARGS...
  local name=$1; shift
  "$build/$@" --out "$t/$name.1.tsv" > /dev/null 2> "$t/$name.1.log" || { echo "FAIL: $name, one process:"; tail -3 "$t/$name.1.log"; fail=1; return; }
  "${mpi[@]}" "$build/$@" --out "$t/$name.2.tsv" > /dev/null 2> "$t/$name.2.log" || { echo "FAIL: $name, 2 ranks:"; tail -3 "$t/$name.2.log"; fail=1; return; }
  if diff <(rows "$t/$name.1.tsv") <(rows "$t/$name.2.tsv") > "$t/$name.diff"; then
    echo "ok: $name: $(grep -vc '^#' "$t/$name.1.tsv") lines identical (1 process, 2 ranks)"
  else
    echo "FAIL: $name differs:"; head -5 "$t/$name.diff"; fail=1
  fi
}
check imoto imoto_fig5_table1 --levels 5,6
check table4_2 thesis_table4_2 --levels 5,6
check table4_4 thesis_table4_4 --levels 5,6
check heat4_6 thesis_heat --table 4.6 --levels 5
# A second run of 2 ranks reuses every unit (nothing to deal out) and keeps the file's rows.
"${mpi[@]}" "$build/imoto_fig5_table1" --levels 5,6 --out "$t/imoto.2.tsv" > /dev/null 2>&1 \
  && diff -q <(rows "$t/imoto.1.tsv") <(rows "$t/imoto.2.tsv") > /dev/null \
  || { echo "FAIL: a rerun on 2 ranks changed the file"; fail=1; }
# --verify is a one-process check.
if "${mpi[@]}" "$build/imoto_fig5_table1" --levels 5 --out "$t/imoto.1.tsv" --verify > "$t/v.log" 2>&1; then
  echo "FAIL: 2 ranks accepted --verify"; fail=1
else
  grep -q "run on one process" "$t/v.log" || { echo "FAIL: no message for --verify on 2 ranks"; cat "$t/v.log"; fail=1; }
fi
[ $fail -eq 0 ] && echo "mpi_matches_serial: every study kind gives the same rows on 2 ranks"
exit $fail
