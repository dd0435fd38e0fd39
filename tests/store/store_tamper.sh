#!/usr/bin/env bash
# The store check must catch every way a user could damage a store file by hand (issue 27):
# on a copy of the committed Table 4.4 file, each edit below is applied alone and
# verify_store.sh (make test's store check) must fail; the unedited copy must pass.  The
# last case runs the [paper] tier under a comma-decimal locale: its counts must not move.
#
# usage: store_tamper.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=$(cd "${1:?usage: store_tamper.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: store_tamper.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
f=thesis_table4_4.tsv
orig=$src/results/paper/$f
failed=0 n=0
# The rel_error of the 2^-9 h10 quartic row, and the first data line's rel_error.
row9=$(awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
  $c["h_rule"]=="h10" && $c["weight"]=="quartic_polynomial" && $c["level"]==9 { print NR; exit }' "$orig")
[ -n "$row9" ] || { echo "FAIL: no 2^-9 h10 quartic row in $orig"; exit 1; }

case_() {  # case_ NAME SED_OR_SHELL: apply the edit to a fresh copy; the check must fail
  local name=$1 edit=$2
  n=$((n + 1))
  rm -rf "$t/s" && mkdir "$t/s" && cp "$orig" "$t/s/$f"
  (cd "$t/s" && eval "$edit") || { echo "FAIL $name: the edit itself failed"; failed=$((failed + 1)); return; }
  if [ -f "$t/s/$f" ] && cmp -s "$orig" "$t/s/$f"; then
    echo "FAIL $name: the edit changed nothing"; failed=$((failed + 1)); return
  fi
  if bash "$src/tests/store/verify_store.sh" "$build" "$t/s" --verify "$f" >"$t/log" 2>&1; then
    echo "FAIL $name: the store check passed"; sed 's/^/   /' "$t/log" | tail -5; failed=$((failed + 1))
  else
    echo "caught $name: $(grep -m1 'error\|MISSING\|differs\|FAILED' "$t/log")"
  fi
}
first=$(awk -F'\t' '/^#/ { next } !h++ { next } { print NR; exit }' "$orig")
cell() {  # cell LINE COLUMN-NAME VALUE-AWK: an awk edit of one cell
  echo "awk -F'\t' 'BEGIN{OFS=\"\t\"} /^#/{print;next} !h++{for(i=1;i<=NF;i++)c[\$i]=i;print;next} NR==$1{\$c[\"$2\"]=$3} {print}' $f > x && mv x $f"
}
case_ "inf in a number"           "$(cell "$first" rel_error '"inf"')"
case_ "1e999 in a number"         "$(cell "$first" rel_error '"1e999"')"
case_ "a rate-level row x 0.851"  "$(cell "$row9" rel_error '$c["rel_error"]*0.851')"
case_ "a rate-level row x 0.5"    "$(cell "$row9" rel_error '$c["rel_error"]*0.5')"
case_ "a row deleted"             "sed -i '${row9}d' $f"
case_ "the file deleted"          "rm $f"
case_ "a row cut short"           "sed -i '\$s/\t[^\t]*\t[^\t]*\$//' $f"
case_ "a cell added to a row"     "sed -i '${first}s/\$/\tX/' $f"
case_ "a duplicate row"           "sed -n '${first}p' $f >> $f"
case_ "CRLF line endings"         "sed -i 's/\$/\r/' $f"
case_ "a UTF-8 byte-order mark"   "sed -i '1s/^/\xEF\xBB\xBF/' $f"
case_ "a header parameter edited" "sed -i 's/^# tol = .*/# tol = 1e-8/' $f"
case_ "a provenance line edited"  "sed -i 's/^# git_revision = .*/# git_revision = 000000000000/' $f"
case_ "the command line edited"   "sed -i 's/^# command = .*/# command = build\/thesis_table4_4 --seed 2/' $f"
case_ "the checked cell edited"   "$(cell "$first" checked '"recheck 2026-01-01 by hand"')"
case_ "a stray profile line"      "sed -i '1i # profile = quick' $f"

# The unedited copy passes.
rm -rf "$t/s" && mkdir "$t/s" && cp "$orig" "$t/s/$f"
bash "$src/tests/store/verify_store.sh" "$build" "$t/s" --verify "$f" >"$t/log" 2>&1 ||
  { echo "FAIL: the unedited copy was rejected"; tail -5 "$t/log"; failed=$((failed + 1)); }

# A comma-decimal locale changes nothing in the [paper] tier's counts (where the locale exists).
if locale -a 2>/dev/null | grep -qi '^de_DE\.utf'; then
  a=$(cd "$src" && bash tests/paper/check_verdicts.sh "$build" . 2>&1 | tail -1)
  b=$(cd "$src" && LC_ALL=de_DE.UTF-8 bash tests/paper/check_verdicts.sh "$build" . 2>&1 | tail -1)
  n=$((n + 1))
  [ "$a" = "$b" ] && echo "caught nothing to catch: the locale leaves the counts as they are" ||
    { echo "FAIL: under de_DE.UTF-8 the counts move: '$b' against '$a'"; failed=$((failed + 1)); }
fi
echo "store_tamper: $n cases, $failed failed"
[ "$failed" -eq 0 ]
