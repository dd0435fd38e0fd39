#!/usr/bin/env bash
# The modes that write nothing work on a read-only store (issue 43): on a copy of a store file
# in a folder nobody may write, --census and --verify pass, and a run that would write is
# refused with one line before any work.  As root (where permissions do not bind) the three
# run as user nobody (setpriv); as another user, as that user.
#
# usage: readonly_store.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: readonly_store.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: readonly_store.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'chmod -R u+w "$t"; rm -rf "$t"' EXIT
chmod 755 "$t"
as=()
if [ "$(id -u)" = 0 ]; then
  command -v setpriv >/dev/null || { echo "skipped: root without setpriv cannot drop its permissions"; exit 0; }
  as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  # nobody must be able to reach the build and the copy
  "${as[@]}" test -x "$build/thesis_table4_4" || { echo "skipped: user nobody cannot run $build/thesis_table4_4"; exit 0; }
fi
mkdir "$t/s" && cp "$src/results/paper/thesis_table4_4.tsv" "$t/s/" && chmod 444 "$t/s/thesis_table4_4.tsv" && chmod 555 "$t/s"
f=$t/s/thesis_table4_4.tsv failed=0
run() { "${as[@]}" "$build/thesis_table4_4" --profile paper --out "$f" "$@"; }
run --census >"$t/log" 2>&1 || { echo "FAIL: --census on a read-only store: $(tail -1 "$t/log")"; failed=1; }
run --verify --levels 5 >"$t/log" 2>&1 || { echo "FAIL: --verify on a read-only store: $(tail -1 "$t/log")"; failed=1; }
if run --levels 5,6,10 >"$t/log" 2>&1; then
  echo "FAIL: a run that writes was not refused on a read-only store"; failed=1
elif [ "$(wc -l <"$t/log")" -ne 1 ]; then
  echo "FAIL: the refusal is not one line:"; sed 's/^/   /' "$t/log"; failed=1
else
  echo "refused as it should: $(cat "$t/log")"
fi
[ -z "$(ls -A "$t/s" | grep -v '^thesis_table4_4.tsv$')" ] || { echo "FAIL: files appeared: $(ls "$t/s")"; failed=1; }
[ $failed -eq 0 ] && echo "ok: --census and --verify work on a read-only store"
exit $failed
