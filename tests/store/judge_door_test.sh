#!/usr/bin/env bash
# The store's door for the judging pass (StoreChecks::store, judge/snapshot.hpp), on copies of
# the store: gpm store-rates and gpm rate-levels stop with exit 4 naming the file for a
# hand-edited number (its seal broken), a hand-edited header line (its seal), rows pasted from
# another realization's file (the seal binds the file's name), another reading's file under a
# registered name, and a missing registered file; the untouched store passes.  (Not guarded, so not tested: an edit
# resealed by hand: only the recomputation finds it, tests/store/verify_full_test.sh.)
# usage: judge_door_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: judge_door_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: judge_door_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
fail=0
judge() {  # judge STORE: exit codes of store-rates and rate-levels, and their messages
  "$build/gpm" store-rates --store "$1" --published "$src/tables/published" --out "$t/r.tsv" > "$t/msg" 2>&1
  local a=$?
  "$build/gpm" rate-levels --store "$1" --published "$src/tables/published" --out "$t/l.tsv" >> "$t/msg" 2>&1
  echo "$a $?"
}
expect() {  # expect WHAT CODES FILE: both commands exited so, and the message names FILE
  if [ "$2" != "4 4" ] || ! grep -q "$3" "$t/msg"; then
    echo "FAIL: $1: exit codes $2 (want 4 4), messages:"; cat "$t/msg"; fail=1
  fi
}
fresh() { rm -rf "$t/s"; cp -r "$src/results/paper" "$t/s"; }
fresh
[ "$(judge "$t/s")" = "0 0" ] || { echo "FAIL: the untouched store was refused:"; cat "$t/msg"; fail=1; }
# 1. One stored error edited by hand (Table 4.4, V_i = dx^2, h15 quintic at 2^-9).
f=$t/s/thesis_table4_4_cellvol.tsv
awk -F'\t' -v OFS='\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; print; next }
  !d && $c["level"] == 9 && $c["h_rule"] == "h15" { $c["rel_error"] = $c["rel_error"] / 2; d = 1 } { print }' \
  "$f" > "$t/x" && mv "$t/x" "$f"
expect "a hand-edited number" "$(judge "$t/s")" "thesis_table4_4_cellvol.tsv: data row"
# 1b. A provenance line of its header edited by hand: the header's seal.
fresh
sed -i 's/^# git_revision = .*/# git_revision = 000000000000/' "$f"
expect "a hand-edited header line" "$(judge "$t/s")" "thesis_table4_4_cellvol.tsv: its header's seal"
# 1c. The 2^-9 rows of seed 2's file pasted over seed 3's (a merge accident, issue 61 case 6.10):
# the seals bind each row to its file's name.
fresh
g2=$t/s/thesis_table4_4_cellvol_seed2.tsv g3=$t/s/thesis_table4_4_cellvol_seed3.tsv
awk -F'\t' 'FNR == 1 { file++ } /^#/ { if (file == 2) print; next } !h[file]++ { for (i = 1; i <= NF; i++) c[$i] = i; if (file == 2) print; next }
  file == 1 { if ($c["level"] == 9) pasted[++n] = $0; next }
  $c["level"] == 9 { if (!done) { for (i = 1; i <= n; i++) print pasted[i]; done = 1 } next } { print }' "$g2" "$g3" > "$t/x" && mv "$t/x" "$g3"
expect "rows pasted from another realization's file" "$(judge "$t/s")" "thesis_table4_4_cellvol_seed3.tsv: data row"
# 2. Another reading's file copied over the identified reading's.
fresh
cp "$t/s/thesis_table4_6_dtexact.tsv" "$t/s/thesis_table4_6_h15_dtexact_cellvol.tsv"
expect "another reading's file under the identified name" "$(judge "$t/s")" "thesis_table4_6_h15_dtexact_cellvol.tsv: written with"
# 3. The identified reading's file deleted.
fresh
rm "$t/s/thesis_table4_6_h15_dtexact_cellvol.tsv"
expect "a missing registered file" "$(judge "$t/s")" "thesis_table4_6_h15_dtexact_cellvol.tsv: missing"
[ $fail -eq 0 ] && echo "judge door: an edited number, an edited header, pasted rows, a renamed file and a missing file each stop the judges with exit 4"
exit $fail
