#!/usr/bin/env bash
# gpm store-seal against a removed seal (issue 61, item 5): in a git clone whose committed
# version of a store file is sealed, a copy stripped of its seal column (after a number was
# edited) is refused and left as it was; a file git has never seen sealed is sealed, and the
# sealing is logged in rechecks.log with its date and who did it; a copy whose header line was
# edited is refused too.
# usage: seal_guard_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: seal_guard_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: seal_guard_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
command -v git > /dev/null || { echo "seal guard: no git, nothing to check"; exit 0; }
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
fail=0
strip() {  # strip FILE: an error halved, the seal column and the header's seal dropped
  awk -F'\t' -v OFS='\t' '/^# header_seal = / { next } /^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; NF--; print; next }
    !d { $c["rel_error"] = $c["rel_error"] / 2; d = 1 } { NF--; print }' "$1" > "$1.x" && mv "$1.x" "$1"
}
mkdir -p "$t/repo/store" && cd "$t/repo" && git init -q && git config user.email t@t && git config user.name t
cp "$src/results/paper/thesis_table4_4_seed2.tsv" store/a.tsv
git add store/a.tsv && git commit -qm sealed
strip store/a.tsv
cp store/a.tsv "$t/stripped"
"$build/gpm" store-seal store/a.tsv > "$t/msg" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q "restore the file from git" "$t/msg" && cmp -s store/a.tsv "$t/stripped" ||
  { echo "FAIL: a stripped copy of a sealed file was not refused (exit $rc):"; cat "$t/msg"; fail=1; }
# A file git never saw sealed (a new one, here untracked) is sealed, and logged.
cp "$t/stripped" store/b.tsv
"$build/gpm" store-seal store/b.tsv > "$t/msg" 2>&1 || { echo "FAIL: sealing an untracked file failed:"; cat "$t/msg"; fail=1; }
grep -q $'^b.tsv\t.* rows\tsealed .* by .*(gpm store-seal)$' store/rechecks.log ||
  { echo "FAIL: the sealing is not logged in rechecks.log:"; cat store/rechecks.log 2>/dev/null; fail=1; }
# A header line edited by hand (issue 61, case 6.3): its seal no longer matches, and
# store-seal does not renew it.
mkdir -p store2 && cp "$src/results/paper/thesis_table4_4_seed2.tsv" store2/
sed -i 's/^# git_revision = .*/# git_revision = 000000000000/' store2/thesis_table4_4_seed2.tsv
cp store2/thesis_table4_4_seed2.tsv "$t/edited"
"$build/gpm" store-seal store2/thesis_table4_4_seed2.tsv > "$t/msg" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q "edited header is not sealed again" "$t/msg" && cmp -s store2/thesis_table4_4_seed2.tsv "$t/edited" ||
  { echo "FAIL: an edited header was sealed again (exit $rc):"; cat "$t/msg"; fail=1; }
[ $fail -eq 0 ] && echo "seal guard: a removed seal or an edited header is not sealed again; a sealing is logged"
exit $fail
