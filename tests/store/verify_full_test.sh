#!/usr/bin/env bash
# verify_store_full.sh on a copy of one store file (Table 4.4, the cheap levels): the first run
# logs a sealed "agree" line per level, a second run resumes (verifies nothing again), levels
# in parts log a line per unit (and a file's units beyond its census's --only are verified), two
# lanes (--jobs 2) log each level once (wide jobs after them on all the cores), and a stored number changed by hand (seal recomputed,
# so only the recomputation can tell) makes its level "differs" with exit 4, by the rows' own
# path and by the cheaper one (--cheap: preconditioned CG for plain CG's rows, at 1e-6: an
# edit of 1e-5 is still caught).  A level's price comes from an earlier line of its path
# where that measured fewer seconds than its rows, a part's from its own line alike.
# usage: verify_full_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: verify_full_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: verify_full_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/store"
# Levels 5 and 6 only, so that the test is quick; the file keeps its header and seals.
awk -F'\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; print; next }
  $c["level"] <= 6' "$src/results/paper/thesis_table4_4.tsv" > "$t/store/thesis_table4_4.tsv"
run() { bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --log "$t/verified.log" thesis_table4_4 "$@"; }
fail=0
run > "$t/out1" 2>&1 || { echo "FAIL: the first run failed:"; cat "$t/out1"; exit 1; }
n=$(grep -c '	agree	' "$t/verified.log")
[ "$n" -eq 2 ] || { echo "FAIL: expected 2 agree lines (levels 5, 6), got $n:"; cat "$t/verified.log"; fail=1; }
awk -F'\t' 'NR > 1 && (length($14) != 16 || $13 != "own") { bad = 1 } END { exit bad }' "$t/verified.log" ||
  { echo "FAIL: a log line without its 16-digit seal"; fail=1; }
run > "$t/out2" 2>&1
grep -q '^verify_store_full: 0 (file, level) to verify' "$t/out2" ||
  { echo "FAIL: the second run did not resume (it found work again):"; cat "$t/out2"; fail=1; }
# Parts (--split-above 0: every level by its units, --only h rule,weight): the whole levels'
# lines above vouch for their parts; on a log of its own, one sealed line per unit the file
# holds, each path naming its part, and a rerun resumes.
run --split-above 0 > "$t/out8" 2>&1
grep -q '^verify_store_full: 0 (file, level) to verify' "$t/out8" ||
  { echo "FAIL: a whole level's line did not vouch for its parts:"; cat "$t/out8"; fail=1; }
units=$(awk -F'\t' '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next }
  { print $c["level"], $c["h_rule"] "," $c["weight"] }' "$t/store/thesis_table4_4.tsv" | sort -u)
run --split-above 0 --log "$t/parts.log" > "$t/out9" 2>&1 || { echo "FAIL: the run in parts failed:"; cat "$t/out9"; fail=1; }
got=$(awk -F'\t' 'NR > 1 && $9 == "agree" && length($14) == 16 && $13 ~ /^own --only / { print $3, substr($13, 12) }' "$t/parts.log" | sort)
[ -n "$units" ] && [ "$got" = "$units" ] ||
  { echo "FAIL: parts: want one agree line per (level, h rule, weight):"; echo "$units"; echo "got:"; echo "$got"; fail=1; }
run --split-above 0 --log "$t/parts.log" > "$t/out10" 2>&1
grep -q '^verify_store_full: 0 (file, level) to verify' "$t/out10" ||
  { echo "FAIL: the run in parts did not resume:"; cat "$t/out10"; fail=1; }
# A file holding units beyond its census's --only (cellvol_tau's census: h15; here h10 rows
# added at level 5 by the program itself): its level goes in parts, the h10 units verified too.
tau=thesis_table4_4_cellvol_tau
awk -F'\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; print; next }
  $c["level"] == 5' "$src/results/paper/$tau.tsv" > "$t/store/$tau.tsv"
"$build/thesis_table4_4" --volumes cell --solver tau --seed 1 --levels 5 --only h10 --profile paper \
  --out "$t/store/$tau.tsv" > "$t/tau.out" 2>&1 || { echo "FAIL: could not add h10 rows:"; cat "$t/tau.out"; exit 1; }
bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --log "$t/tau.log" "$tau" > "$t/out11" 2>&1
n=$(awk -F'\t' '$9 == "agree" && $13 ~ /^own --only h10,/' "$t/tau.log" | wc -l)
[ "$n" -eq 3 ] || { echo "FAIL: the h10 units beyond the census's --only h15: want 3 agree lines, got $n:"; cat "$t/out11"; fail=1; }
# A recomputation that leaves rows out (here a program that adds --only h15 itself) is
# "incomplete", exit 4, never agree (the log and the suite say so).
mkdir -p "$t/short"
ln -s "$build/gpm" "$t/short/gpm"
printf '#!/bin/sh\nexec "%s/thesis_table4_4" "$@" --only h15\n' "$build" > "$t/short/thesis_table4_4"
chmod +x "$t/short/thesis_table4_4"
bash "$src/tests/store/verify_store_full.sh" "$t/short" "$t/store" --log "$t/short.log" thesis_table4_4 > "$t/out12" 2>&1
rc=$?
n=$(awk -F'\t' '$9 == "incomplete"' "$t/short.log" | wc -l)
[ $rc -eq 4 ] && [ "$n" -eq 2 ] && ! grep -q '	agree	' "$t/short.log" ||
  { echo "FAIL: rows left out: want exit 4 and 2 incomplete lines, got exit $rc:"; cat "$t/out12" "$t/short.log"; fail=1; }
# Two lanes from one queue: both levels logged once each, sealed, the cells whole.
rm -f "$t/verified.log"
run --jobs 2 > "$t/out6" 2>&1 || { echo "FAIL: the run in two lanes failed:"; cat "$t/out6"; fail=1; }
levels=$(awk -F'\t' 'NR > 1 && $9 == "agree" && length($14) == 16 && NF == 14 { print $3 }' "$t/verified.log" | sort | tr '\n' ' ')
[ "$levels" = "5 6 " ] && grep -q '^verify_store_full: 2 verified this run, 0 differ, .* in 2 lanes$' "$t/out6" ||
  { echo "FAIL: two lanes: want one sealed agree line for each of levels 5 and 6, got '$levels':"; cat "$t/out6" "$t/verified.log"; fail=1; }
# Wide jobs (--wide-above 0: every job): after the lanes, one at a time on all the cores.
rm -f "$t/verified.log"
run --jobs 2 --wide-above 0 > "$t/out13" 2>&1 || { echo "FAIL: the wide jobs failed:"; cat "$t/out13"; fail=1; }
levels=$(awk -F'\t' 'NR > 1 && $9 == "agree" && length($14) == 16 { print $3 }' "$t/verified.log" | sort | tr '\n' ' ')
thin=$(awk -F'\t' 'NR > 1 && $12 ~ /, 1 thread$/' "$t/verified.log" | wc -l)
[ "$levels" = "5 6 " ] && grep -q '^verify_store_full: the lanes are done; 2 wide job' "$t/out13" &&
  { [ "$(nproc)" -eq 1 ] || [ "$thin" -eq 0 ]; } ||
  { echo "FAIL: wide jobs: want levels 5 and 6 logged once, on all the cores, got '$levels':"; cat "$t/out13" "$t/verified.log"; fail=1; }
# The price by measurement: an earlier line of the level by the same path (another code, so
# the level is still to do) prices it at its seconds times the threads its machine cell names,
# where fewer than the rows' estimate; a line of more seconds, a part's line or another path's
# leaves the estimate.  Dry runs on a copy whose rows say 1000 times their seconds.
mkdir -p "$t/priced"
awk -F'\t' -v OFS='\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1
    s = ("seconds" in c) ? c["seconds"] : c["time_s"]; print; next } { $s = $s * 1000; print }' \
  "$t/store/thesis_table4_4.tsv" > "$t/priced/thesis_table4_4.tsv"
price() {  # price LOG_LINE_CELLS...: level 6's one-thread price on a log holding that one line
  { head -1 "$t/verified.log"; [ $# -eq 0 ] || printf '2026-01-01T00:00:00Z\tthesis_table4_4\t6\tthesis_table4_4\t000000000000\t1\t1\t0\tagree\t%s\t0\t%s\t%s\t0\n' "$@"; } > "$t/priced.log"
  bash "$src/tests/store/verify_store_full.sh" "$build" "$t/priced" --log "$t/priced.log" --dry-run thesis_table4_4 2>&1 |
    awk -F'\t' '$1 == "thesis_table4_4" && $2 == 6 { print $8 }'
}
est=$(price)
got=$(price 3 "M, 2 cores, 1 thread" own) got2=$(price 3 "M, 2 cores" own) more=$(price 999999 "M, 2 cores" own)
part=$(price 3 "M, 2 cores, 1 thread" "own --only h15,quartic_polynomial") other=$(price 3 "M, 2 cores, 1 thread" "--solver tau")
[ "$got" = 3.0 ] && [ "$got2" = 6.0 ] && [ "$more" = "$est" ] && [ "$part" = "$est" ] && [ "$other" = "$est" ] &&
  awk -v e="$est" 'BEGIN { exit !(e > 6) }' ||
  { echo "FAIL: measured price: want 3.0, 6.0 and the estimate $est (> 6) three times, got '$got' '$got2' '$more' '$part' '$other'"; fail=1; }
# A part's line prices that part where the level goes in parts (--split-above 0), the other
# parts keep their estimates; a part's line that compared every row of the level (thesis_heat
# never read --only) prices the whole level.
parts() {  # parts ROWS: level 6's parts and prices on a log holding one part's line of ROWS rows
  { head -1 "$t/verified.log"; printf '2026-01-01T00:00:00Z\tthesis_table4_4\t6\tthesis_table4_4\t000000000000\t1\t%s\t0\tagree\t3\t0\tM, 2 cores, 1 thread\town --only h15,quartic_polynomial\t0\n' "$1"; } > "$t/priced.log"
  bash "$src/tests/store/verify_store_full.sh" "$build" "$t/priced" --log "$t/priced.log" --dry-run "${@:2}" thesis_table4_4 2>&1 |
    awk -F'\t' '$1 == "thesis_table4_4" && $2 == 6 { print $3, $8 }'
}
held6=$(awk -F'\t' '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next } $c["level"] == 6 { n++ } END { print n }' "$t/priced/thesis_table4_4.tsv")
by_part=$(parts 1 --split-above 0) whole=$(parts "$held6")
mine=$(awk '$1 == "h15,quartic_polynomial" { print $2 }' <<<"$by_part")
others=$(awk '$1 != "h15,quartic_polynomial" && $2 + 0 > 3 { n++ } END { print n + 0 }' <<<"$by_part")
[ "$mine" = 3.0 ] && [ "$others" -ge 1 ] && [ "$others" -eq $(($(wc -l <<<"$by_part") - 1)) ] && [ "$whole" = "- 3.0" ] ||
  { echo "FAIL: a part's measured price: want 3.0 for its part, the estimate (> 3) for the $others others, '- 3.0' for a line of all $held6 rows, got:"; echo "$by_part"; echo "whole: $whole"; fail=1; }
# A lane's bounds (--budget, --until) take a job's seconds on the lane's threads: rows made on
# two threads (made_on edited, seconds times 1000, resealed) need twice their seconds on a lane
# of one.  A budget between the two takes no job; an --until already past neither (said once up front, each job left, once); an --until an hour away takes both levels.
mkdir -p "$t/two"
awk -F'\t' -v OFS='\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; NF--; print; next }
  { $c["seconds"] = $c["seconds"] * 1000; $c["made_on"] = "M, 2 threads, 2026-01-01"; NF--; print }' \
  "$t/store/thesis_table4_4.tsv" > "$t/two/thesis_table4_4.tsv"
"$build/gpm" store-seal "$t/two/thesis_table4_4.tsv" > "$t/seal.out" 2>&1 || { echo "FAIL: store-seal refused:"; cat "$t/seal.out"; exit 1; }
two() { bash "$src/tests/store/verify_store_full.sh" "$build" "$t/two" --log "$t/two.log" --jobs 2 thesis_table4_4 "$@"; }
b=$(two --dry-run 2>&1 | awk -F'\t' '$1 == "thesis_table4_4" { x = ($7 + $8) / 2; if (m == "" || x < m) m = x } END { printf "%d", m }')
rm -f "$t/two.log"; OMP_NUM_THREADS=1 two --budget "$b" > "$t/out14" 2>&1
n14=$(grep -c '	agree	' "$t/two.log")
rm -f "$t/two.log"; two --until "1 minute ago" > "$t/out15" 2>&1
n15=$(grep -c '	agree	' "$t/two.log") stops=$(grep -c ' would end after .* (lane [12]): left' "$t/out15")
rm -f "$t/two.log"; two --until "1 hour" > "$t/out16" 2>&1
n16=$(grep -c '	agree	' "$t/two.log")
[ "$b" -gt 0 ] && [ "$n14" -eq 0 ] && grep -q "budget of $b s reached" "$t/out14" && [ "$n15" -eq 0 ] && [ "$stops" -eq 2 ] && grep -q '^verify_store_full: --until is .*, already past: no job will start' "$t/out15" && [ "$n16" -eq 2 ] && ! grep -q 'already past' "$t/out16" ||
  { echo "FAIL: lane bounds: want 0 levels under budget $b (between the path's and one thread's estimate), 0 under a past --until (two jobs left, got $stops) and 2 within an hour, got $n14, $n15, $n16:"; cat "$t/out14" "$t/out15" "$t/out16"; fail=1; }
# A job that does not fit is left and the next tried: level 5 first by the path's estimate
# (34.5 s, made on two threads: 69 s on one), level 6 after it (about 40 s, made on one);
# one lane of one thread under a budget of 50 s takes level 6 alone.
mkdir -p "$t/mix"
awk -F'\t' -v OFS='\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; NF--; print; next }
  $c["level"] == 5 { $c["seconds"] = $c["seconds"] * 1000; $c["made_on"] = "M, 2 threads, 2026-01-01" }
  $c["level"] == 6 { $c["seconds"] = $c["seconds"] * 115; $c["made_on"] = "M, 1 threads, 2026-01-01" } { NF--; print }' \
  "$t/store/thesis_table4_4.tsv" > "$t/mix/thesis_table4_4.tsv"
"$build/gpm" store-seal "$t/mix/thesis_table4_4.tsv" > "$t/seal.out" 2>&1 || { echo "FAIL: store-seal refused:"; cat "$t/seal.out"; exit 1; }
OMP_NUM_THREADS=1 bash "$src/tests/store/verify_store_full.sh" "$build" "$t/mix" --log "$t/mix.log" --budget 50 thesis_table4_4 > "$t/out18" 2>&1
mixed=$(awk -F'\t' 'NR > 1 && $9 == "agree" { print $3 }' "$t/mix.log" | tr '\n' ' ')
[ "$mixed" = "6 " ] && grep -q 'thesis_table4_4 level 5 (estimated 69.0 s) left' "$t/out18" ||
  { echo "FAIL: a job that does not fit: want level 5 left and level 6 taken, got '$mixed':"; cat "$t/out18"; fail=1; }
two --until "not a time" > "$t/out17" 2>&1
[ $? -eq 2 ] && grep -q "^verify_store_full.sh: --until 'not a time'" "$t/out17" || { echo "FAIL: a bad --until was not refused:"; cat "$t/out17"; fail=1; }
run --jobs 0 > "$t/out7" 2>&1
[ $? -eq 2 ] && grep -q "^verify_store_full.sh: --jobs '0'" "$t/out7" || { echo "FAIL: --jobs 0 was not refused:"; cat "$t/out7"; fail=1; }
# The cheaper path: both levels agree at its tolerance, logged with the path's options.
rm -f "$t/verified.log"
run --cheap --cheap-above 0 > "$t/out4" 2>&1 || { echo "FAIL: the cheap path failed:"; cat "$t/out4"; fail=1; }
n=$(awk -F'\t' '$9 == "agree" && $13 == "--solver tau"' "$t/verified.log" | wc -l)
[ "$n" -eq 2 ] || { echo "FAIL: expected 2 agree lines by --solver tau, got $n:"; cat "$t/verified.log"; fail=1; }
# One error at level 6 changed by hand (by `factor`), the seal column dropped and the file
# sealed anew (gpm store-seal): the seals pass, only the recomputation can tell.
edit() {
  cp "$t/orig.tsv" "$t/store/thesis_table4_4.tsv"
  awk -F'\t' -v OFS='\t' -v f="$1" '/^#/ { print; next }
    !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; NF--; print; next }
    $c["level"] == 6 && !done { $c["rel_error"] = $c["rel_error"] * f; done = 1 } { NF--; print }' \
    "$t/store/thesis_table4_4.tsv" > "$t/x" && mv "$t/x" "$t/store/thesis_table4_4.tsv"
  "$build/gpm" store-seal "$t/store/thesis_table4_4.tsv" > "$t/seal.out" 2>&1 ||
    { echo "FAIL: gpm store-seal refused the test's file:"; cat "$t/seal.out"; exit 1; }
  rm -f "$t/verified.log"
}
cp "$t/store/thesis_table4_4.tsv" "$t/orig.tsv"
for how in "1.01 own" "1.00001 --cheap --cheap-above 0"; do
  set -- $how
  edit "$1"
  f=$1; shift
  if [ "$1" = own ]; then run > "$t/out3" 2>&1; else run "$@" > "$t/out3" 2>&1; fi
  rc=$?
  [ $rc -eq 4 ] || { echo "FAIL: a stored number changed by $f gave exit $rc, not 4 ($*):"; cat "$t/out3"; fail=1; }
  grep -q '	6	thesis_table4_4	.*	differs	' "$t/verified.log" ||
    { echo "FAIL: level 6 is not logged as differing ($*):"; cat "$t/verified.log"; fail=1; }
done
# Two heat files of one reading (Tables 4.5 and 4.6, h15, exact dt, V_i = dx^2; levels 5 and
# 6, which both hold) go by the propagator in one shared run, one line per file naming the
# tables; a resealed edit of Table 4.6's level 6 makes that line alone "differs".
heat=(thesis_table4_5_h15_dtexact_cellvol thesis_table4_6_h15_dtexact_cellvol)
for f in "${heat[@]}"; do
  awk -F'\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; print; next }
    $c["level"] == 5 || $c["level"] == 6' "$src/results/paper/$f.tsv" > "$t/store/$f.tsv"
done
awk -F'\t' -v OFS='\t' '/^#/ { print; next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; NF--; print; next }
  $c["level"] == 6 && !done { $c["rel_error"] = $c["rel_error"] * 1.01; done = 1 } { NF--; print }' \
  "$t/store/${heat[1]}.tsv" > "$t/x" && mv "$t/x" "$t/store/${heat[1]}.tsv"
"$build/gpm" store-seal "$t/store/${heat[1]}.tsv" > "$t/seal.out" 2>&1 ||
  { echo "FAIL: gpm store-seal refused the test's heat file:"; cat "$t/seal.out"; exit 1; }
rm -f "$t/verified.log"
bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --log "$t/verified.log" --cheap --cheap-above 0 \
  "${heat[@]}" > "$t/out5" 2>&1
rc=$?
shared=$(awk -F'\t' '$13 == "--propagator auto --solver tau --table 4.5,4.6"' "$t/verified.log")
verdicts=$(awk -F'\t' '{ print $2, $3, $9 }' <<<"$shared" | sort | tr '\n' ';')
want="${heat[0]} 5 agree;${heat[0]} 6 agree;${heat[1]} 5 agree;${heat[1]} 6 differs;"
[ $rc -eq 4 ] && [ "$verdicts" = "$want" ] ||
  { echo "FAIL: the shared heat run: exit $rc (want 4), lines '$verdicts' (want '$want'):"; cat "$t/out5"; fail=1; }
# A heat file in parts: one job per weight, selected by --weights (thesis_heat lists its units
# itself and refuses --only), each line comparing that weight's rows alone.
bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --log "$t/heatparts.log" --cheap --cheap-above 0 \
  --split-above 0 "${heat[0]}" > "$t/out14" 2>&1 || { echo "FAIL: the heat file in parts failed:"; cat "$t/out14"; fail=1; }
want=$(awk -F'\t' '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next }
  { n[$c["level"] " " $c["weight"]]++ } END { for (k in n) print k, n[k] }' "$t/store/${heat[0]}.tsv" | sort)
got=$(awk -F'\t' 'NR > 1 && $9 == "agree" && match($13, / --weights [^ ]+$/) { print $3, substr($13, RSTART + 11), $7 }' "$t/heatparts.log" | sort)
[ -n "$want" ] && [ "$got" = "$want" ] ||
  { echo "FAIL: heat parts: want one agree line per (level, weight) with its rows:"; echo "$want"; echo "got:"; echo "$got"; cat "$t/out14"; fail=1; }
# A part's line that compared every row of its level (a thesis_heat "part" under --only, which
# the program never read before it refused it) vouches for the whole level; one that compared
# a part's rows, for that part alone.
code=$("$build/gpm" fingerprint thesis_heat | awk -F'\t' '$1 == "thesis_heat" { print $2 }')
all5=$(awk -F'\t' '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next } $c["level"] == 5 { n++ } END { print n }' "$t/store/${heat[0]}.tsv")
pending5() {  # ROWS: level 5's jobs still to do when the log holds one "part" line of ROWS rows
  { head -1 "$t/heatparts.log"
    printf '2026-01-01T00:00:00Z\t%s\t5\tthesis_heat\t%s\t1\t%s\t0\tagree\t1\t1\tM, 2 cores\t--propagator auto --solver tau --only quartic_polynomial\t0\n' "${heat[0]}" "$code" "$1"; } > "$t/whole.log"
  bash "$src/tests/store/verify_store_full.sh" "$build" "$t/store" --log "$t/whole.log" --cheap --cheap-above 0 --split-above 0 \
    --dry-run "${heat[0]}" 2>&1 | awk -F'\t' '$2 == 5' | wc -l
}
w=$(pending5 "$all5") p=$(pending5 3)
[ "$w" -eq 0 ] && [ "$p" -eq 2 ] ||
  { echo "FAIL: a part line of all $all5 rows should leave level 5 done (left: $w), one of 3 rows two weights to do (left: $p)"; fail=1; }
[ $fail -eq 0 ] && echo "verify_store_full: logs sealed lines, resumes, goes in parts, a resealed edit differs (own and cheaper path; heat tables in one shared run, each file its own verdict)"
exit $fail
