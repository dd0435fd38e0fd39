#!/usr/bin/env bash
# make test's check of tables/beyond_plan.sh, the report's table of the units past the
# documents: on the committed store every row of tables/beyond.tsv is listed, read by its
# census and priced by the plan (a fixed calibration: plan_calibration.tsv); Table 4.7's
# identified reading at 2^-10 is stored whole (6 of 6 units, nothing owed); on a copy whose
# file lost its 2^-10 rows, the same row owes all 6 units at the plan's whole price.
# usage: beyond_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: beyond_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: beyond_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
cal=$src/tests/store/plan_calibration.tsv
f=thesis_table4_7_h15_dtexact_cellvol.tsv
cell() {  # cell TABLE COLUMN: the cell of the row (f, level 10), by header
  awk -F'\t' -v f="$f" -v k="$2" '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["store_file"] == f && $c["level"] == 10 { print $c[k] }' "$1"
}
bash "$src/tables/beyond_plan.sh" "$build" "$src/results/paper" "$cal" "$tmp/full.tsv" ||
  { echo "FAIL: beyond_plan.sh on the committed store"; exit 1; }
listed=$(awk -F'\t' '/^#/ { next } !h++ { next } { n++ } END { print n + 0 }' "$tmp/full.tsv")
wanted=$(awk -F'\t' '/^#/ { next } !h++ { next } { n++ } END { print n + 0 }' "$src/tables/beyond.tsv")
[ "$listed" -eq "$wanted" ] || { echo "FAIL: $listed rows listed, tables/beyond.tsv has $wanted"; fail=1; }
unread=$(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["census"] != "read" || !($c["plan_h"] > 0) || $c["units"] < 1 { n++ } END { print n + 0 }' "$tmp/full.tsv")
[ "$unread" -eq 0 ] || { echo "FAIL: $unread rows not read by their census or not priced"; fail=1; }
[ "$(cell "$tmp/full.tsv" stored)/$(cell "$tmp/full.tsv" units)/$(cell "$tmp/full.tsv" missing_h)" = 6/6/0.00 ] ||
  { echo "FAIL: $f at 2^-10 is not stored whole (stored/units/missing_h: $(cell "$tmp/full.tsv" stored)/$(cell "$tmp/full.tsv" units)/$(cell "$tmp/full.tsv" missing_h))"; fail=1; }
cp -r "$src/results/paper" "$tmp/store"
awk -F'\t' '/^#/ { print; next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; print; next } $c["level"] != 10' \
  "$src/results/paper/$f" > "$tmp/store/$f"
bash "$src/tables/beyond_plan.sh" "$build" "$tmp/store" "$cal" "$tmp/cut.tsv" ||
  { echo "FAIL: beyond_plan.sh on the cut copy"; exit 1; }
[ "$(cell "$tmp/cut.tsv" stored)/$(cell "$tmp/cut.tsv" missing)" = 0/6 ] ||
  { echo "FAIL: the cut copy's $f should owe 6 units at 2^-10, it says stored $(cell "$tmp/cut.tsv" stored), missing $(cell "$tmp/cut.tsv" missing)"; fail=1; }
[ "$(cell "$tmp/cut.tsv" missing_h)" = "$(cell "$tmp/cut.tsv" plan_h)" ] ||
  { echo "FAIL: the cut copy's missing units are not priced at the level's whole plan"; fail=1; }
[ $fail -eq 0 ] && echo "units past the documents: $listed rows read and priced; $f at 2^-10 stored whole, and owed whole ($(cell "$tmp/cut.tsv" missing_h) h) once cut"
exit $fail
