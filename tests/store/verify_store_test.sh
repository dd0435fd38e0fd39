#!/bin/bash
# verify_store.sh must fail on a store whose numbers were changed: a copy of the committed
# Table 4.4 file with one coarse error changed by 1 % is rejected (its seal no longer
# matches; a changed number under a valid seal is the [store] unit tests' case), the
# unchanged copy passes.  (An earlier version reported its output filter's status and
# passed both.)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=${1:?usage: verify_store_test.sh BUILD_DIR SOURCE_DIR}
src=${2:?usage: verify_store_test.sh BUILD_DIR SOURCE_DIR}
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/good" "$t/bad"
f=thesis_table4_4.tsv
cp "$src/results/paper/$f" "$t/good/$f"
awk -F'\t' 'BEGIN { OFS = "\t" } /^#/ { print; next }
  !h++ { for (i = 1; i <= NF; i++) c[$i] = i; print; next }
  $c["level"] == 5 && !done++ { $c["rel_error"] = $c["rel_error"] * 1.01 } { print }' \
  "$src/results/paper/$f" > "$t/bad/$f"
cmp -s "$t/good/$f" "$t/bad/$f" && { echo "FAIL: the fixture was not changed"; exit 1; }
bash "$src/tests/store/verify_store.sh" "$build" "$t/good" --verify "$f" > "$t/good.log" 2>&1 ||
  { echo "FAIL: the unchanged store was rejected"; cat "$t/good.log"; exit 1; }
if bash "$src/tests/store/verify_store.sh" "$build" "$t/bad" --verify "$f" > "$t/bad.log" 2>&1; then
  echo "FAIL: a store with a changed number passed"; cat "$t/bad.log"; exit 1
fi
grep -q "line [0-9]* (h_rule h10, weight .*, level 5): its seal does not match" "$t/bad.log" ||
  { echo "FAIL: the rejection does not name the row"; cat "$t/bad.log"; exit 1; }
echo "verify_store_test: the unchanged store passes, the changed one is rejected naming the row"
