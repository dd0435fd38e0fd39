#!/usr/bin/env bash
# In the paper profile make writes nothing into the result store but the studies' own files
# (issue 61, case 9.1): rate tables, side outputs (…_finite.tsv, imoto_pi3_printed.tsv) and
# every diagnostic go to data/paper, a plain folder.  In a scratch copy of the make files whose
# data/paper is still the older layout's link to the whole store, `make -n PROFILE=paper data`
# must (1) replace that link by a folder, (2) name results/paper only for registered study
# files (STUDY_FILES of build/studies.mk) and (3) name some, so the check is not vacuous.
#
# usage: paper_outputs.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: paper_outputs.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: paper_outputs.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
for f in Makefile mk tables figures paper; do ln -s "$src/$f" "$t/$f"; done
mkdir -p "$t/results/paper" "$t/data"
for f in predictions diagnostics; do ln -s "$src/results/$f" "$t/results/$f"; done
ln -s ../results/paper "$t/data/paper"
(cd "$t" && make -n --no-print-directory PROFILE=paper BUILD="$build" data) >"$t/dry.txt" 2>&1 ||
  { echo "FAIL: make -n PROFILE=paper data failed:"; tail -3 "$t/dry.txt"; exit 1; }
failed=0
if [ -L "$t/data/paper" ] || [ ! -d "$t/data/paper" ]; then
  echo "FAIL: data/paper is still a link to the store (or missing), not a folder"; failed=1
fi
studies=$(sed -n 's/^STUDY_FILES := //p' "$build/studies.mk" | tr ' ' '\n' | sed 's/$/.tsv/')
named=$(grep -o 'results/paper/[^ ;)"]*' "$t/dry.txt" | sort -u)
[ -n "$named" ] || { echo "FAIL: no recipe writes a study file into results/paper (nothing checked)"; failed=1; }
for p in $named; do
  printf '%s\n' "$studies" | grep -qx "${p#results/paper/}" ||
    { echo "FAIL: the paper profile writes $p, which is not a study's file"; failed=1; }
done
[ $failed -eq 0 ] && echo "ok: the paper profile names $(printf '%s\n' $named | wc -l) study files in results/paper and nothing else; data/paper is a folder"
exit $failed
