#!/usr/bin/env bash
# --replace and the quick-profile cache against the store's files (issue 61, items 3-4), on
# copies in a results/paper folder: a run of another table or volumes reading with --replace is refused (exit 2) and the
# file stays byte for byte; a sealed file in a results/paper folder whose header was edited to
# `profile = quick` is not dropped as a cache by a quick run.
# usage: replace_guard_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: replace_guard_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: replace_guard_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
fail=0
mkdir -p "$t/results/paper"
refused() {  # refused FILE COMMAND...: exit 2 and FILE (a copy in a results/paper folder) unchanged
  local f=$1; shift
  cp "$src/results/paper/$f" "$t/results/paper/$f"
  "$@" --out "$t/results/paper/$f" --replace > "$t/msg" 2>&1
  local rc=$?
  if [ $rc -ne 2 ] || ! cmp -s "$t/results/paper/$f" "$src/results/paper/$f"; then
    echo "FAIL: $* --replace on $f: exit $rc (want 2), file $(cmp -s "$t/results/paper/$f" "$src/results/paper/$f" && echo unchanged || echo CHANGED)"
    cat "$t/msg"; fail=1
  fi
}
refused thesis_table4_6.tsv "$build/thesis_heat" --table 4.5 --levels 5 --profile paper
refused thesis_table4_4_cellvol.tsv "$build/thesis_table4_4" --levels 5 --profile paper
refused thesis_table4_4_seed3.tsv "$build/thesis_table4_4" --levels 5 --profile paper --seed 2
# The header edited to quick, in a store folder: a quick run of another seed (the file is
# seed 1's) keeps the sealed rows, as the file's own run would.
f=$t/results/paper/thesis_table4_4.tsv
sed 's/^# profile = paper$/# profile = quick/' "$src/results/paper/thesis_table4_4.tsv" > "$f"
before=$(grep -vc '^#' "$f")
"$build/thesis_table4_4" --profile quick --seed 2 --levels 5 --out "$f" > "$t/msg" 2>&1
after=$(grep -vc '^#' "$f")
[ "$after" -ge "$before" ] || { echo "FAIL: a quick run dropped a store file's rows ($before -> $after lines)"; cat "$t/msg"; fail=1; }
[ $fail -eq 0 ] && echo "replace guard: another reading's --replace refused, a store file is no quick cache"
exit $fail
