#!/usr/bin/env bash
# Ctrl-C during a make-driven study never deletes the store file (issue 43): in a scratch
# copy of the project's make files, Table 4.4's store file (paper profile, data/paper linking
# into results/paper) is seeded with two levels; `make data/paper/thesis_table4_4.tsv` is
# started with the program marked new (-W), and interrupted as a terminal's Ctrl-C does
# (SIGINT to make's process group) while a finer level computes.  The file must still be
# there, hold the seeded units (census) and resume.  Without make's .PRECIOUS list make
# prints "Deleting file" and the file is gone.
#
# usage: make_interrupt.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: make_interrupt.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: make_interrupt.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
for f in Makefile mk tables figures paper; do ln -s "$src/$f" "$t/$f"; done
mkdir -p "$t/results/paper"
store=$t/results/paper/thesis_table4_4.tsv
"$build/thesis_table4_4" --profile paper --levels 5,6 --out "$store" >/dev/null 2>&1 ||
  { echo "FAIL: seeding the store file failed"; exit 1; }
rows=$(grep -vc '^#' "$store")
# make's process group gets SIGINT after 4 s (the recheck of 2^-5/2^-6 takes well under a
# second; the paper levels run to 2^-9, tens of seconds).
(cd "$t" && python3 - "$build" <<'PY' >"$t/make.log" 2>&1
import os, signal, subprocess, sys, time
p = subprocess.Popen(["make", "--no-print-directory", "PROFILE=paper", "BUILD=" + sys.argv[1],
                      "-W", sys.argv[1] + "/thesis_table4_4", "data/paper/thesis_table4_4.tsv"],
                     preexec_fn=lambda: (signal.signal(signal.SIGINT, signal.SIG_DFL), os.setpgid(0, 0)))
time.sleep(4)
os.killpg(p.pid, signal.SIGINT)
print("make exit", p.wait())
PY
)
failed=0
grep -q 'make exit 0' "$t/make.log" && { echo "FAIL: make finished before the interrupt (nothing tested)"; failed=1; }
if [ ! -f "$store" ]; then
  echo "FAIL: the store file is gone after the interrupt"; sed 's/^/   /' "$t/make.log" | tail -5; exit 1
fi
grep -q 'Deleting file' "$t/make.log" && { echo "FAIL: make tried to delete a data file"; failed=1; }
now=$(grep -vc '^#' "$store")
[ "$now" -ge "$rows" ] || { echo "FAIL: $rows rows before, $now after"; failed=1; }
"$build/thesis_table4_4" --profile paper --levels 5,6 --out "$store" --census >/dev/null 2>&1 ||
  { echo "FAIL: the seeded units are not all in the file after the interrupt"; failed=1; }
# and the study resumes from it: the seeded levels are reused, not recomputed
"$build/thesis_table4_4" --profile paper --levels 5,6 --out "$store" 2>&1 | grep -q 'nothing to compute' ||
  { echo "FAIL: a rerun does not reuse the stored units"; failed=1; }
[ $failed -eq 0 ] && echo "ok: interrupted make left $store whole ($rows rows before, $now after) and resumable"
exit $failed
