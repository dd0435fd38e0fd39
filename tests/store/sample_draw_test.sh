#!/usr/bin/env bash
# The sampled store check's draw (sample_draw.py) does what it states: over 200 seeds the
# mean number of units drawn per run is within 10 % of the sum of the stated chances, every
# reachable unit has a chance above zero, and some units are reachable (not vacuous), some of
# them only by a cheaper path (Table 4.4's plain-CG levels by the preconditioned solver).
#
# usage: sample_draw_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=${1:?usage: sample_draw_test.sh BUILD_DIR SOURCE_DIR} src=${2:?usage: sample_draw_test.sh BUILD_DIR SOURCE_DIR}
out=$(SAMPLE_SEED=draw-test SAMPLE_COVERAGE=200 bash "$src/tests/store/verify_sample.sh" "$build" "$src/results/paper") ||
  { echo "FAIL: the coverage pass failed"; exit 1; }
printf '%s\n' "$out"
awk -F'\t' '{ v[$1] = $2 }
  END { bad = 0
    if (v["reachable"] + 0 < 1) { print "FAIL: no unit is reachable"; bad = 1 }
    if (v["reachable_by_cheaper_path"] + 0 < 1) { print "FAIL: no unit is reached by a cheaper path"; bad = 1 }
    if (!(v["min_chance"] + 0 > 0)) { print "FAIL: a reachable unit has no chance"; bad = 1 }
    d = v["counted_per_run_mean"] - v["expected_per_run"]; if (d < 0) d = -d
    if (d > 0.1 * v["expected_per_run"]) { printf "FAIL: %s drawn a run over 200 seeds, %s stated\n", v["counted_per_run_mean"], v["expected_per_run"]; bad = 1 }
    if (!bad) print "ok: the draw matches its stated chances"
    exit bad }' <<<"$out"
