#!/usr/bin/env bash
# make test's check of tables/store_census.sh, the report's table of what the store owes: on
# the committed store every file is read and none lacks a unit; on a copy whose Table 4.4
# seed-2 file lost its 2^-9 rows, that file alone is reported with its 6 units at level 9,
# priced by a plan summary fixture (360 s for the level's 6 units: 0.10 h).
# usage: census_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: census_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: census_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
printf 'study\tlevel\tunits\tN\tpair_interactions\ttime_s\tpeak_mib\tmethod\ttrimmed\n' > "$tmp/plan_summary.tsv"
printf 'thesis_table4_4\t9\t6\t378225\t1\t360\t1\tassembled\tno\n' >> "$tmp/plan_summary.tsv"
col() {  # col FILE STORE_FILE COLUMN: a cell of the census table, by header
  awk -F'\t' -v f="$2" -v k="$3" '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["store_file"] == f { print $c[k] }' "$1"
}
bash "$src/tables/store_census.sh" "$build" "$src/results/paper" "$tmp/plan_summary.tsv" "$tmp/full.tsv" ||
  { echo "FAIL: store_census.sh on the committed store"; exit 1; }
files=$(awk -F'\t' '/^#/ { next } !h++ { next } { n++ } END { print n + 0 }' "$tmp/full.tsv")
owed=$(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["units_missing"] != "0" || $c["census"] != "read" { n++ } END { print n + 0 }' "$tmp/full.tsv")
registered=$("$build/gpm" study --store-rows | wc -l)
[ "$files" -eq "$registered" ] || { echo "FAIL: the census lists $files files, the registry $registered"; fail=1; }
[ "$owed" -eq 0 ] || { echo "FAIL: the committed store owes units in $owed files"; fail=1; }
cp -r "$src/results/paper" "$tmp/store"
f=thesis_table4_4_seed2.tsv
awk -F'\t' '/^#/ { print; next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; print; next } $c["level"] != 9' \
  "$src/results/paper/$f" > "$tmp/store/$f"
bash "$src/tables/store_census.sh" "$build" "$tmp/store" "$tmp/plan_summary.tsv" "$tmp/cut.tsv" ||
  { echo "FAIL: store_census.sh on the cut copy"; exit 1; }
[ "$(col "$tmp/cut.tsv" "$f" units_missing)" = 6 ] || { echo "FAIL: $f lacks 6 units, the census says '$(col "$tmp/cut.tsv" "$f" units_missing)'"; fail=1; }
[ "$(col "$tmp/cut.tsv" "$f" missing_by_level)" = 9:6 ] || { echo "FAIL: missing_by_level of $f is not 9:6"; fail=1; }
[ "$(col "$tmp/cut.tsv" "$f" predicted_missing_h)" = 0.10 ] || { echo "FAIL: predicted time of $f is not 0.10 h"; fail=1; }
[ "$(col "$tmp/cut.tsv" thesis_table4_4_seed3.tsv units_missing)" = 0 ] || { echo "FAIL: an untouched file owes units"; fail=1; }
[ $fail -eq 0 ] && echo "store census: $files files read, none owes a unit; a copy without one file's 2^-9 rows owes 6 units (0.10 h by the fixture plan)"
exit $fail
