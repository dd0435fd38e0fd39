#!/usr/bin/env bash
# verify_background.sh on a copy of one store file (Table 4.4, levels 5 and 6): a started run
# goes on by itself from frozen copies, refuses a second start, and a merge appends exactly the
# lines it added to the store's log (a second merge adds none); a drained run takes no job
# (VERIFY_STOP_FILE, what `drain` creates); status names each lane's last job.
# usage: verify_background_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: verify_background_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: verify_background_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
export VERIFY_BG_DIR=$t/bg
mkdir -p "$t/store"
awk -F'\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; print; next }
  $c["level"] <= 6' "$src/results/paper/thesis_table4_4.tsv" > "$t/store/thesis_table4_4.tsv"
head -1 "$src/results/paper/verified.log" > "$t/store/verified.log"
bg() { bash "$src/tests/store/verify_background.sh" "$@"; }
fail=0
bg start "$build" "$t/store" thesis_table4_4 > "$t/out1" 2>&1 || { echo "FAIL: start:"; cat "$t/out1"; exit 1; }
bg start "$build" "$t/store" thesis_table4_4 > "$t/out2" 2>&1 &&
  { echo "FAIL: a second start (run going, or its lines not merged) was not refused:"; cat "$t/out2"; fail=1; }
for _ in $(seq 1 300); do kill -0 "$(cat "$t/bg/pid")" 2>/dev/null || break; sleep 0.2; done
kill -0 "$(cat "$t/bg/pid")" 2>/dev/null && { echo "FAIL: the run did not end"; cat "$t/bg/progress"; exit 1; }
[ "$(wc -l < "$t/store/verified.log")" -eq 1 ] || { echo "FAIL: the run wrote the store's log itself"; fail=1; }
# status names what each lane took last (one lane here: level 6, the dearer, after level 5).
bg status > "$t/status" 2>&1
grep -q '^last taken: .* lane 1 starts thesis_table4_4 level 6 (own path), estimated ' "$t/status" &&
  [ "$(grep -c '^last taken: ' "$t/status")" -eq 1 ] ||
  { echo "FAIL: status: want the one lane's last job (level 6):"; cat "$t/status"; fail=1; }
bg merge "$t/store" > "$t/out3" 2>&1
n=$(awk -F'\t' 'NR > 1 && $9 == "agree" && length($14) == 16 { print $3 }' "$t/store/verified.log" | sort | tr '\n' ' ')
[ "$n" = "5 6 " ] && grep -q 'merged 2 line' "$t/out3" || { echo "FAIL: merge: want levels 5 and 6 once, got '$n':"; cat "$t/out3" "$t/bg/progress"; fail=1; }
bg merge "$t/store" > "$t/out4" 2>&1
grep -q 'merged 0 line' "$t/out4" && [ "$(wc -l < "$t/store/verified.log")" -eq 3 ] ||
  { echo "FAIL: a second merge added lines:"; cat "$t/out4"; fail=1; }
bg merge "$t" > "$t/out5" 2>&1 && { echo "FAIL: a merge into another store was not refused"; fail=1; }
# A drained run (its stop file there before any job) takes no job; the log gains nothing.
head -1 "$src/results/paper/verified.log" > "$t/store/verified.log"
: > "$t/stop"
VERIFY_STOP_FILE=$t/stop bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --jobs 2 thesis_table4_4 > "$t/out6" 2>&1
grep -q '^verify_store_full: 0 verified this run' "$t/out6" && [ "$(wc -l < "$t/store/verified.log")" -eq 1 ] ||
  { echo "FAIL: a drained run took jobs:"; cat "$t/out6"; fail=1; }
[ $fail -eq 0 ] && echo "verify_background: runs from frozen copies, one at a time, merges its lines once"
exit $fail
