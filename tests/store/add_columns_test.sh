#!/usr/bin/env bash
# gpm store-add-columns on copies of store files (issue 61, item 8): a control character in
# --add is refused; with --files a,b and b bad, a is left as it was; a file whose lock another
# process holds is refused; a good call adds the column, reseals and logs.
# usage: add_columns_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: add_columns_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: add_columns_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
# The copies keep their names (a seal binds its file's name: gpm/io/seal.hpp).
a=thesis_table4_4_seed2.tsv b=thesis_table4_4_seed3.tsv
cp "$src/results/paper/$a" "$src/results/paper/$b" "$t/"
cp "$t/$a" "$t/a0"; cp "$t/$b" "$t/b0"
fail=0
add() { "$build/gpm" store-add-columns --after storage "$@" > "$t/msg" 2>&1; }
add --add "$(printf 'x=1\t2')" --files "$t/$a"
[ $? -eq 2 ] && cmp -s "$t/$a" "$t/a0" || { echo "FAIL: a tab in --add was not refused cleanly:"; cat "$t/msg"; fail=1; }
# b bad: one cell edited, its seal broken.
sed -i '0,/\tassembled\t/s//\tassembled \t/' "$t/$b"
add --add x=1 --files "$t/$a,$t/$b"
[ $? -eq 2 ] && cmp -s "$t/$a" "$t/a0" || { echo "FAIL: with b bad, a was changed or the call passed:"; cat "$t/msg"; fail=1; }
cp "$t/b0" "$t/$b"
# A lock held by another process.
flock "$t/$a.lock" sleep 5 & sleep 0.5
add --add x=1 --files "$t/$a"
rc=$?
wait
[ $rc -eq 2 ] && grep -q "lock" "$t/msg" && cmp -s "$t/$a" "$t/a0" ||
  { echo "FAIL: a held lock did not stop the call (exit $rc):"; cat "$t/msg"; fail=1; }
add --add x=1 --files "$t/$a,$t/$b" || { echo "FAIL: the good call failed:"; cat "$t/msg"; fail=1; }
grep -q $'storage\tx\t' "$t/$a" && grep -q "columns added" "$t/rechecks.log" ||
  { echo "FAIL: the column or the log line is missing"; fail=1; }
[ $fail -eq 0 ] && echo "store-add-columns: control characters, a bad second file and a held lock leave every file as it was"
exit $fail
