#!/usr/bin/env bash
# One run over Tables 4.5-4.7 (issue 58, item 2) gives each table the rows of its own run, bit
# for bit: each table alone into its own file, then the three together verifying those files
# (store --verify: every number and the subspace compared) must report a largest difference of
# exactly 0 for each.  Both propagators: the Krylov subspace shared by the tables (each its own
# size group) and the stepper's block of every table's series.
# usage: shared_subspace_test.sh BUILD_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: shared_subspace_test.sh BUILD_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
fail=0
common=(--h-rule h15 --dt-rule exact --volumes cell --levels 5 --profile quick --weights piecewise_quintic_polynomial)
for how in krylov stepped; do
  mkdir -p "$t/$how"
  for table in 4.5 4.6 4.7; do
    "$build/thesis_heat" --table "$table" "${common[@]}" --propagator "$how" \
      --out "$t/$how/thesis_table${table/./_}.tsv" > "$t/alone.log" 2>&1 || { echo "FAIL: Table $table alone ($how)"; cat "$t/alone.log"; fail=1; }
  done
  "$build/thesis_heat" --table 4.5,4.6,4.7 "${common[@]}" --propagator "$how" \
    --out "$t/$how/thesis_table{table}.tsv" --verify > "$t/shared.log" 2>&1
  rc=$?
  verdicts=$(grep -c 'max relative difference 0 (tolerance' "$t/shared.log")
  if [ $rc -ne 0 ] || [ "$verdicts" -ne 3 ]; then
    echo "FAIL: the three tables together ($how) against each alone: exit $rc, $verdicts of 3 files equal bit for bit"
    grep '\[store\]' "$t/shared.log"; fail=1
  fi
done
# The progress line names the tables a shared subspace serves; a pattern without {table} is refused.
"$build/thesis_heat" --table 4.5,4.6 "${common[@]}" --out "$t/one.tsv" > "$t/msg" 2>&1
rc=$?
if [ $rc -ne 2 ] || ! grep -q '{table}' "$t/msg" || [ -e "$t/one.tsv" ]; then
  echo "FAIL: two tables into one file: exit $rc (want 2, a message naming {table}, no file)"; cat "$t/msg"; fail=1
fi
[ $fail -eq 0 ] && echo "shared subspace: Tables 4.5-4.7 in one run equal each table's own run bit for bit (Krylov and stepped)"
exit $fail
