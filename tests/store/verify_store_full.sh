#!/usr/bin/env bash
# The whole result store recomputed, level by level, resumably (issue 58, item 3; the last item
# of issue 42).  make test's check (verify_store.sh) recomputes only the cheap coarse units;
# this walks every (store file, level) the store holds, cheapest first by the time its rows
# recorded, and recomputes it with `--verify` by the path its rows name (the heat rows' own
# propagator; storage as the program chooses it: the numbers, not the path's bookkeeping, are
# compared: store.hpp).  Each (file, level) verified appends one sealed line to the log:
#
#   date  file  level  program  code  units  rows  max_rel_diff  verdict  seconds  stored_s  machine  path  seal
#
# path: "own" (the rows' own path) or, with --cheap, the options of an independent and
# cheaper path (issue 58, item 3): Table 4.4's plain-CG files by CG preconditioned with the
# lattice's tau matrix ("--solver tau", compared at 1e-6 relative); the heat files by the
# propagator with fewer predicted products per series, a Krylov subspace for most stepped rows
# ("--propagator auto", at 1e-4 where a row's propagator differs from its own), their implicit
# steps, if stepped, preconditioned ("--solver tau").  Tolerances: kStoreSolverPathRelTol and
# kStorePropagatorPathRelTol in src/gpm/studies/run/store.hpp, ten times the largest
# difference measured between the paths.  The rows' own path stays on the sample verified by
# it (every line of path "own") and on make test's draw.  Heat files of one reading and level
# that go by the propagator are verified in one run (thesis_heat --table 4.5,4.6: one
# Laplacian and one Krylov subspace, each table sized as alone, so each file meets its own
# numbers): one line per file, its path ending in the tables' list ("--table 4.5,4.6") and its
# seconds those of the shared run.
#
# seal: the first 16 hex digits of the SHA-256 of the line's other cells, a tripwire for
# hand edits.  A (file, level) whose line carries the program's current code is skipped, so a
# rerun continues where the log stops and a code change (a new fingerprint) starts it anew;
# an interrupted level leaves no line.  A difference is a line with verdict "differs" and
# exit 4 at the end (the log keeps it: a difference is a finding, not an accident); a run that
# compared fewer rows than the file holds at the level (or part) is "incomplete", exit 4 too.
#
# Parts: a level estimated above --split-above seconds on one thread goes as one job per value
# of its unit key (unit_key in census_lib.sh: each part its own Laplacian or pass) that the
# file holds at the level, with --only in place of the census's selection (a heat file's by
# --weights: thesis_heat lists its units itself and refuses --only); its line's path ends
# "--only PART" or "--weights PART".  A part lands before a session's machine goes where a
# whole level of hours would not.  A level is done when a whole-level line, a line for each of
# its parts, or a part's line that compared every row of the level carries the current code.
# A file whose census selects with --only always goes in parts, so its rows beyond that
# selection are verified too.
#
# usage: verify_store_full.sh BUILD STORE [--log FILE] [--budget SECONDS] [--until TIME]
#                             [--max-unit SECONDS] [--cheap [--cheap-above SECONDS]] [--split-above SECONDS]
#                             [--wide-above SECONDS] [--jobs N] [--dry-run] [FILE...]
#   --log       default STORE/verified.log
#   --budget    take no (file, level) whose estimate would take its lane past this many
#               seconds (default: no limit); --max-unit: skip levels whose stored time
#               exceeds this (default: none)
#   --until     take no job that would end after this time (anything `date -d` reads, e.g.
#               16:30Z), so that a session's last jobs land before its machine goes.  Both
#               bounds use a job's estimate on the threads its lane has: its seconds on one
#               thread over those threads, or its estimate by the path where more (a row
#               made on two threads needs up to twice its seconds on one).  A job that does
#               not fit is left for this run and the lane goes on to the next (the queue's
#               order is the path's estimate, not the lane's: a later job may fit).
#   --cheap     the cheaper paths above for levels of more than 60 stored seconds (a cheaper
#               level by its own path, at 1e-9; --cheap-above SECONDS moves the bound); the
#               budget, the order and the price then use each
#               level's estimated seconds by that path (cheap_s: Table 4.4's assembly plus its
#               solve scaled by 15 iterations over its own count, the preconditioned solver's
#               11-13 at every level measured, results/bench/pcg_*; a heat row's stored time,
#               an upper bound: its path is chosen only where it needs fewer products)
#   --split-above  levels estimated above this many seconds on one thread go in parts (default 3600)
#   --wide-above  with --jobs above 1: jobs of this many seconds or more on one thread run after the
#               lanes, one at a time on all the cores (default 9000)
#   --jobs      N lanes at once, each taking the cheapest job left when its last is done (each
#               program then on its share of the cores, OMP_NUM_THREADS, unless set; a lane's
#               --budget is its own wall time); default 1
#   --dry-run   the price only: each (file, level, part) to do with its stored seconds, and the sum
#   FILE...     only these store files (stems)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/../.." && pwd)/tables/census_lib.sh"
usage="usage: verify_store_full.sh BUILD STORE [--log FILE] [--budget SECONDS] [--until TIME] [--max-unit SECONDS] [--cheap [--cheap-above SECONDS]] [--split-above SECONDS] [--wide-above SECONDS] [--jobs N] [--dry-run] [FILE...]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
build=$1 store=$2
shift 2
[ -x "$build/gpm" ] || { echo "verify_store_full.sh: $build/gpm not found; $usage" >&2; exit 2; }
[ -d "$store" ] || { echo "verify_store_full.sh: $store is not a directory; $usage" >&2; exit 2; }
log=$store/verified.log budget="" until="" max_unit="" dry=0 cheap=0 above=60 lanes=1 split=3600 wide=9000 only=()
while [ $# -gt 0 ]; do
  case $1 in
    --log) log=${2:?--log needs a file}; shift 2 ;;
    --budget) budget=${2:?--budget needs seconds}; shift 2 ;;
    --until) until=$(date -d "${2:?--until needs a time}" +%s 2>/dev/null) ||
               { echo "verify_store_full.sh: --until '$2' is not a time date -d reads" >&2; exit 2; }; shift 2 ;;
    --max-unit) max_unit=${2:?--max-unit needs seconds}; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --cheap) cheap=1; shift ;;
    --cheap-above) above=${2:?--cheap-above needs seconds}; shift 2 ;;
    --split-above) split=${2:?--split-above needs seconds}; shift 2 ;;
    --wide-above) wide=${2:?--wide-above needs seconds}; shift 2 ;;
    --jobs) lanes=${2:?--jobs needs a number}; shift 2 ;;
    -*) echo "verify_store_full.sh: unknown option '$1'; $usage" >&2; exit 2 ;;
    *) only+=("$1"); shift ;;
  esac
done
for n in "$budget" "$max_unit" "$above" "$split" "$wide"; do
  [ -z "$n" ] || [[ $n =~ ^[0-9]+$ ]] || { echo "verify_store_full.sh: '$n' is not a whole number of seconds" >&2; exit 2; }
done
[[ $lanes =~ ^[1-9][0-9]*$ ]] || { echo "verify_store_full.sh: --jobs '$lanes' is not a whole number of 1 or more" >&2; exit 2; }
# A bare time names today: after midnight "01:55Z" is already past and no job would start.
# Said once, up front, rather than only in each job's line.
[ -z "$until" ] || [ "$until" -gt "$(date +%s)" ] ||
  echo "verify_store_full: --until is $(date -u -d "@$until" +%FT%TZ), already past: no job will start (across midnight, give the date too)" >&2
# Lanes share the cores: each program gets its share of threads unless the caller set them
# (before machine_line, so that the log's machine cell says the threads a run had).
threads_set=""
if [ "$lanes" -gt 1 ] && [ -z "${OMP_NUM_THREADS:-}" ]; then
  threads_set=$(nproc)  # the wide jobs' threads, after the lanes
  OMP_NUM_THREADS=$(( threads_set / lanes )); [ "$OMP_NUM_THREADS" -ge 1 ] || OMP_NUM_THREADS=1
  export OMP_NUM_THREADS
fi
header="date	file	level	program	code	units	rows	max_rel_diff	verdict	seconds	stored_s	machine	path	seal"
[ -f "$log" ] || [ $dry = 1 ] || printf '%s\n' "$header" > "$log"
machine=$(machine_line)

# Every (file, level) with its stored seconds: the distinct values of the file's time column
# per level (a unit repeats its time on each of its rows), summed; with --cheap, the path
# and the estimated seconds by it (cheap_s above); last, those seconds on one thread: each
# row's times the threads its made_on cell names (a row made on two threads is wall time of
# two), what a lane of one thread needs on the machine that made the rows.
#
# Where the log holds an earlier verification of the level by the same path (any code: the
# latest line that agreed, of the whole level or of a part that compared all its rows), its
# seconds on one thread (times the threads its machine cell names) replace the estimate when
# fewer: a measurement, not a model; a part's own line prices that part alike (Imoto's m = 5
# at 2^-12 went in 2,102 s on two Zen 5 threads against 9,266 s on one by its rows).  The rows'
# own seconds can be far above what their path costs today: Table 4.5's stepped levels at
# 2^-8 recorded 5,100-9,300 s and went by the propagator in 42-59 s on two Zen 5 threads
# (2026-12-06).  Priced by the rows, they went last, in parts.  A shared run's line
# ("--table 4.5,4.6") counts for each of its files (its seconds cover them all: an upper bound).
todo=$(mktemp) measured=$(mktemp); trap 'rm -f "$todo" "$measured"' EXIT
awk -F'\t' -v OFS='\t' 'FNR > 1 && $9 == "agree" {  # file, level, path, part, seconds on one thread, rows
    p = $13; sub(/ --(only|weights) [^ ]+$/, "", p); sub(/ --table [^ ]+$/, "", p); k = $2 SUBSEP $3 SUBSEP p SUBSEP line_part($13)
    m[k] = ($10 > 1 ? $10 : 1) * threads_in($12); r[k] = $7 }
  END { for (k in m) { split(k, a, SUBSEP); print a[1], a[2], a[3], a[4], m[k], r[k] } }
  '"$line_part_awk"'
  '"$threads_in_awk" "$log" 2>/dev/null > "$measured"
while IFS=$'\t' read -r study file program args census coarse slice; do
  [ ${#only[@]} -eq 0 ] || [[ " ${only[*]} " == *" $file "* ]] || continue
  f=$store/$file.tsv
  [ -f "$f" ] || { echo "verify_store_full.sh: $f is missing" >&2; exit 4; }
  prog=${program%% *}
  code=$("$build/gpm" fingerprint "$prog" | awk -F'\t' -v p="$prog" '$1 == p { print $2 }')
  # The census's options beyond its levels (a file that holds some variants only) go along.
  [ "$census" = "-" ] && census=""
  extra=$(census_options "$census")
  [ "$args" = "-" ] && args=""
  args="${args}${args:+${extra:+ }}${extra}"
  [ -n "$args" ] || args="-"
  path=own
  [ $cheap = 1 ] && path=$(cheaper_path "$prog" "$file" "$f")
  [ "$path" = - ] && path=own
  # Parts: a level is split by its unit key (census_lib.sh) into one job per value the file
  # holds when it would take more than --split-above seconds on one thread (a lane's share),
  # and always where the census selects with --only (Table 4.4's cellvol_tau files: the rows
  # the file holds beyond it are verified too).
  forced=0; [[ " $extra " == *" --only "* ]] && forced=1
  awk -F'\t' -v file="$file" -v program="$program" -v args="$args" -v code="$code" -v path="$path" -v above="$above" \
      -v ukey="$(unit_key "$prog")" -v split_above="$split" -v forced="$forced" -v measured="$measured" '
    BEGIN { nk = split(ukey, uk, ",")
            while ((getline line < measured) > 0) { split(line, a, "\t"); if (a[1] == file) { mk = a[2] SUBSEP a[3] SUBSEP a[4]; mm[mk] = a[5]; mr[mk] = a[6] } } }
    /^#/ { next }
    !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1
         for (i = 1; i <= nk; i++) if (!(uk[i] in c)) nk = 0  # a file without the key goes whole
         t = ("seconds" in c) ? c["seconds"] : c["time_s"]; next }
    { k = $c["level"]; key = k SUBSEP $t; nrow[k]++; x = (path == "own" ? $t : cheaper_s(c, t)); th = made_on_threads(c) * $t
      if (!(key in seen)) { seen[key] = 1; s[k] += $t; e[k] += x; w[k] += th }
      if (nk) { p = unit_part(c, uk, nk); pk = k SUBSEP p
                if (!(pk in ps)) { sep = (k in parts) ? SUBSEP : ""; parts[k] = parts[k] sep p }
                if (!((pk, $t) in pseen)) { pseen[pk, $t] = 1; ps[pk] += $t; pe[pk] += x; pw[pk] += th } } }
    # The seconds of a level or part by the path of its level (stored st, cheaper ex), then on
    # one thread (wt: its seconds times the threads each row was made on): one place for both.
    function by_path(k, st, ex) { return s[k] > above ? ex : st }
    function path_of(k) { return s[k] > above ? path : "own" }  # the path by_path prices
    function one_thread(k, st, ex, wt,   y) { y = by_path(k, st, ex); return st > 0 ? y * wt / st : y }
    function row(k, part, st, ex, wt, f) {  # f: the measured over the estimate, at most 1
      printf "%s\t%s\t%s\t%s\t%s\t%.1f\t%s\t%.1f\t%.1f\t%s\t%d\n", file, k, program, args, code, st,
             path_of(k), by_path(k, st, ex) * f, one_thread(k, st, ex, wt) * f, part, nrow[k] }
    '"$cheaper_seconds_awk"'
    '"$threads_in_awk"'
    '"$unit_part_awk"'
    function less(f, mk, one) {  # f, or the measurement of mk over the estimate one where less
      return (mk in mm) && one > 0 && mm[mk] / one < f ? mm[mk] / one : f }
    END { for (k in s) { one = one_thread(k, s[k], e[k], w[k]); pth = path_of(k)
            f = less(1, k SUBSEP pth SUBSEP "-", one)
            for (mk in mm) { split(mk, b, SUBSEP)  # a part line that compared every row of the level
              if (b[1] == k && b[2] == pth && b[3] != "-" && mr[mk] + 0 >= nrow[k]) f = less(f, mk, one) }
            if (nk && (forced || one * f > split_above + 0)) {
              n = split(parts[k], pl, SUBSEP)
              for (j = 1; j <= n; j++) { pk = k SUBSEP pl[j]
                row(k, pl[j], ps[pk], pe[pk], pw[pk], less(f, k SUBSEP pth SUBSEP pl[j], one_thread(k, ps[pk], pe[pk], pw[pk]))) }
            } else row(k, "-", s[k], e[k], w[k], f) } }' "$f"
done < <("$build/gpm" study --store-rows) | sort -t$'\t' -k8,8g > "$todo"

# Skip what the log already vouches for under the current code.
pending=$(mktemp); trap 'rm -f "$todo" "$measured" "$pending"' EXIT
# A whole level's line vouches for its parts; a part's line (its path ending "--only PART" or,
# for a heat file, "--weights PART") for that part alone, unless it compared every row the
# file holds at the level (thesis_heat never read --only: such a "part" was the whole level).
awk -F'\t' 'NR == FNR { if (FNR > 1 && $9 == "agree") { k = $2 SUBSEP $3 SUBSEP $5; done[k SUBSEP line_part($13)] = 1
                            if ($7 + 0 > rows[k] + 0) rows[k] = $7 }
                          next }
  !(($1 SUBSEP $2 SUBSEP $5 SUBSEP "-") in done) && !(($1 SUBSEP $2 SUBSEP $5 SUBSEP $10) in done) &&
  !(rows[$1 SUBSEP $2 SUBSEP $5] + 0 >= $11 + 0)
  '"$line_part_awk" \
  "$log" "$todo" 2>/dev/null > "$pending" || cp "$todo" "$pending"
total=$(awk -F'\t' '{ s += $6 } END { printf "%.0f", s }' "$pending")
by_path=$(awk -F'\t' '{ s += $8 } END { printf "%.0f", s }' "$pending")
one_thread=$(awk -F'\t' '{ s += $9 } END { printf "%.1f", s / 3600 }' "$pending")
levels_in() { cut -f1,2 "$1" | sort -u | wc -l; }  # (file, level) pairs, parts counted once
n=$(levels_in "$pending") parts_n=$(awk -F'\t' '$10 != "-"' "$pending" | wc -l)
echo "verify_store_full: $n (file, level) to verify$([ "$parts_n" = 0 ] || echo " in $(wc -l < "$pending") jobs ($parts_n of them parts: of levels over $split s, or whose census selects with --only)"), $total s stored time ($(awk -v s="$total" 'BEGIN { printf "%.1f", s / 3600 }') h as recorded)$([ $cheap = 1 ] && echo ", $by_path s ($(awk -v s="$by_path" 'BEGIN { printf "%.1f", s / 3600 }') h) estimated by the cheap path"), $one_thread h on one thread; $(($(levels_in "$todo") - n)) already in $log"
if [ $dry = 1 ]; then
  printf 'file\tlevel\tpart\tprogram\tstored_s\tpath\tcheap_s\tone_thread_s\n'
  awk -F'\t' -v OFS='\t' '{ print $1, $2, $10, $3, $6, $7, $8, $9 }' "$pending"
  exit 0
fi

# Heat files of one reading whose level goes by the propagator (--cheap) share one run: the
# tables' series on one Laplacian and one Krylov subspace (thesis_heat --table 4.5,4.6, each
# table keeping the subspace size it settles at alone, so each file sees its own numbers;
# tests/heat/shared_subspace_test.sh).  Files are of one reading when their names and options
# differ by the table alone.  Such a job's fields hold the files and their stored seconds as
# comma lists, its options the tables' list, and a last field the --out pattern ("-": one file).
# Read by file name, so a group lists its tables in order (4.5, 4.6, 4.7); the jobs are then
# ordered by their estimated seconds.
jobs=$(mktemp); trap 'rm -f "$todo" "$measured" "$pending" "$jobs"' EXIT
awk -F'\t' -v OFS='\t' '
  { part = $10; one = $9; NF = 8  # the part and the one-thread price go last
    rest = $4; sub(/^--table [0-9.]+ ?/, "", rest); table = $4; sub(/^--table /, "", table); sub(/ .*/, "", table)
    shared = $3 == "thesis_heat" && $7 ~ /--propagator auto/ && $1 ~ /^thesis_table4_[567]/ && $4 ~ /^--table /
    key = shared ? $2 SUBSEP $5 SUBSEP $7 SUBSEP rest SUBSEP substr($1, 16) SUBSEP part : NR
    if (!(key in n)) order[++k] = key
    i = ++n[key]; line[key, i] = $0; tab[key, i] = table; tail[key] = rest; suffix[key] = substr($1, 16); pt[key] = part
    ot[key] += one }
  END { for (j = 1; j <= k; j++) { key = order[j]
          if (n[key] == 1) { print line[key, 1], "-", pt[key], ot[key]; continue }
          files = stored = tables = ""; sum = 0
          for (i = 1; i <= n[key]; i++) { split(line[key, i], f, "\t")
            files = files (i > 1 ? "," : "") f[1]; stored = stored (i > 1 ? "," : "") f[6]
            tables = tables (i > 1 ? "," : "") tab[key, i]; sum += f[8] }
          print files, f[2], f[3], "--table " tables (tail[key] == "" ? "" : " " tail[key]), f[5], stored, f[7], sum,
                "thesis_table{table}" suffix[key], pt[key], ot[key] } }' <(sort -t$'\t' -k1,1 "$pending") | sort -t$'\t' -k8,8g > "$jobs"

# The jobs go to --jobs lanes through one queue, cheapest first: a lane takes the next job
# when its last is done (under a lock, as are the log's appends), so a long level holds one
# lane while the others go on.  Each lane keeps its own budget (a lane's seconds are wall
# seconds) and reports its counts in a file; a lane that fails stops the others' next jobs.
queue=$(mktemp -d); trap 'rm -rf "$todo" "$measured" "$pending" "$jobs" "$queue"' EXIT
# Wide jobs: with lanes, a job of --wide-above seconds or more on one thread waits until the lanes
# are done and then runs on all the cores, one at a time: on one thread it would outlast a
# session's machine (a lane's level in progress leaves no line).
if [ "$lanes" -gt 1 ]; then
  awk -F'\t' -v w="$wide" '$11 + 0 < w + 0' "$jobs" > "$queue/jobs"
  awk -F'\t' -v w="$wide" '$11 + 0 >= w + 0' "$jobs" > "$queue/wide"
else cp "$jobs" "$queue/jobs"; : > "$queue/wide"; fi
# VERIFY_STOP_FILE: once that file exists, no lane takes a new job (the lanes finish what they
# hold: verify_background.sh drain).
stopped() { [ -e "$queue/stop" ] || { [ -n "${VERIFY_STOP_FILE:-}" ] && [ -e "$VERIFY_STOP_FILE" ]; }; }
next_job() {  # the queue's first job, removed from it; nothing once empty or stopped
  { flock 9; stopped || { head -1 "$queue/jobs"; sed -i 1d "$queue/jobs"; }; } 9> "$queue/lock"
}
rows_held() {  # FILE LEVEL PART UNIT_KEY: the rows FILE holds at LEVEL (of PART, "-": all)
  awk -F'\t' -v L="$2" -v part="$3" -v ukey="$4" '/^#/ { next }
    !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; nk = split(ukey, uk, ","); next }
    $c["level"] == L && (part == "-" || unit_part(c, uk, nk) == part) { n++ }
    '"$unit_part_awk"'
    END { print n + 0 }' "$1"
}
lane() {  # lane NUMBER: jobs from the queue until it is empty
  spent=0 differs=0 done_n=0
  while job=$(next_job) && [ -n "$job" ]; do
    IFS=$'\t' read -r files level program args code stored path expect pattern part one <<<"$job"
    ukey=$(unit_key "${program%% *}")
    if [ -n "$max_unit" ] && awk -v s="$expect" -v m="$max_unit" 'BEGIN { exit !(s > m) }'; then continue; fi
    # The job's seconds on this lane's threads (--until above), for the bounds and the start line.
    expect=$(awk -v e="$expect" -v o="$one" -v t="${OMP_NUM_THREADS:-$(nproc)}" 'BEGIN { x = o / t; printf "%.1f", (x > e ? x : e) }')
    # The bound it would cross, if any: --budget on the lane's seconds, --until on the clock.
    crossed=$(awk -v s="$expect" -v p="$spent" -v b="$budget" -v n="$(date +%s)" -v u="$until" \
      'BEGIN { if (b != "" && p + s > b) print "budget"; else if (u != "" && n + s > u) print "until" }')
    case $crossed in
      budget) echo "verify_store_full: budget of $budget s reached ($spent s spent$([ "$lanes" = 1 ] || echo " in lane $1")): $files level $level (estimated $expect s) left; rerun to continue"; continue ;;
      until) echo "verify_store_full: $files level $level (estimated $expect s) would end after $(date -u -d "@$until" +%FT%TZ)$([ "$lanes" = 1 ] || echo " (lane $1)"): left; rerun to continue"; continue ;;
    esac
    [ "$args" = "-" ] && args=""
    [ "$path" = own ] || args="$args $path"
    # A part selects its units itself, in place of the census's selection: by key (--only),
    # a heat file's by its weight (--weights: thesis_heat lists its units itself).
    sel=--only; [ "${program%% *}" = thesis_heat ] && sel=--weights
    [ "$part" = - ] || args="$(sed 's/ *--only [^ ]*//' <<<"$args") $sel $part"
    IFS=, read -ra fs <<<"$files"
    IFS=, read -ra st <<<"$stored"
    out=$store/${fs[0]}.tsv
    [ "$pattern" = - ] || out=$store/$pattern.tsv
    # A start line, so that a look at the progress tells what each lane holds and since when
    # (verify_background.sh status): a session that ends soon drains rather than lose a level.
    echo "verify_store_full: $(date -u +%FT%TZ) lane $1 starts $files level $level$([ "$part" = - ] || echo " part $part") ($path path), estimated $expect s"
    t0=$(date +%s)
    # shellcheck disable=SC2086
    log_out=$("$build"/$program $args --profile paper --levels "$level" --out "$out" --verify 2>&1)
    rc=$?
    secs=$(( $(date +%s) - t0 )); spent=$((spent + secs))
    [ $rc -eq 0 ] || [ $rc -eq 4 ] || { echo "verify_store_full: $files level $level: exit $rc"; tail -3 <<<"$log_out"; : > "$queue/stop"; exit 1; }
    # A shared run logs one line per file, each with the run's seconds and the tables it shared.
    logged_path=$path
    [ ${#fs[@]} -eq 1 ] || logged_path="$path ${args%% --*}"
    [ "$part" = - ] || logged_path="$logged_path $sel $part"
    for i in "${!fs[@]}"; do
      file=${fs[$i]}
      # The file's own report: its "[store] verify" line and the "differs" lines after it.
      seg=$(awk -v head="[store] verify $store/$file.tsv:" 'index($0, "[store] verify ") == 1 { on = index($0, head) == 1 }
        on' <<<"$log_out")
      line=$(grep -m1 '^\[store\] verify' <<<"$seg")
      [ -n "$line" ] || { echo "verify_store_full: $file level $level: no verify report for it"; tail -3 <<<"$log_out"; : > "$queue/stop"; exit 1; }
      units=$(sed -n 's/.*: \([0-9]*\) units recomputed.*/\1/p' <<<"$line")
      rows=$(sed -n 's/.* \([0-9]*\) rows compared.*/\1/p' <<<"$line")
      diff=$(sed -n 's/.*max relative difference \([^ ]*\) .*/\1/p' <<<"$line")
      tol=$(sed -n 's/.*(tolerance \([^,)]*\).*/\1/p' <<<"$line")
      # A level the file holds in part (a census that stores some θ or variants only): the units
      # it lacks are recomputed too and reported "not in the file"; the rows it holds decide.
      others=$(grep '^\[store\]   differs: ' <<<"$seg" | grep -vc ': not in the file$')
      missing=$(sed -n 's/.*recomputed (\([0-9]*\) not in the file).*/\1/p' <<<"$line")
      [ -n "$units" ] && [ -n "$missing" ] && units=$((units - missing))
      # Every row the file holds at the level (or part) must have been compared: a selection
      # that leaves some out (a census's --only) is "incomplete", not agree.
      held=$(rows_held "$store/$file.tsv" "$level" "$part" "$ukey")
      if [ "${rows:-0}" -lt "$held" ]; then verdict=incomplete; differs=$((differs + 1))
      elif [[ $line == *": agree" ]] && [ "${rows:-0}" -gt 0 ]; then verdict=agree
      elif [ "$others" -eq 0 ] && [ "${rows:-0}" -gt 0 ] &&
           awk -v d="${diff:-1}" -v t="${tol:-1e-9}" 'BEGIN { exit !(d + 0 <= t + 0) }'; then verdict=agree
      else verdict=differs; differs=$((differs + 1)); fi
      cells="$(date -u +%Y-%m-%dT%H:%M:%SZ)	$file	$level	${program%% *}	$code	${units:-0}	${rows:-0}	${diff:-NA}	$verdict	$secs	${st[$i]}	$machine	$logged_path"
      seal=$(printf '%s' "$cells" | sha256sum | cut -c1-16)
      { flock 9; printf '%s\t%s\n' "$cells" "$seal" >> "$log"; } 9> "$queue/lock"
      done_n=$((done_n + 1))
      echo "verify_store_full: $file level $level ($logged_path path): $verdict (max rel diff ${diff:-NA}, $secs s; stored ${st[$i]} s)"
    done
  done
  echo "$done_n $differs $spent" > "$queue/lane$1"
}
for ((j = 1; j <= lanes; j++)); do lane "$j" & done
failed=0
for pid in $(jobs -p); do wait "$pid" || failed=1; done
if [ $failed -eq 0 ] && ! stopped && [ -s "$queue/wide" ]; then
  echo "verify_store_full: the lanes are done; $(wc -l < "$queue/wide") wide job(s) of $wide s or more on one thread, one at a time on all the cores"
  [ -z "$threads_set" ] || { export OMP_NUM_THREADS=$threads_set; machine=$(machine_line); }
  mv "$queue/wide" "$queue/jobs"
  lane wide || failed=1
fi
read -r done_n differs spent < <(cat "$queue"/lane* 2>/dev/null | awk '{ n += $1; d += $2; s += $3 } END { print n + 0, d + 0, s + 0 }')
echo "verify_store_full: $done_n verified this run, $differs differ, $spent s$([ "$lanes" = 1 ] || echo " in $lanes lanes")"
[ $failed -eq 0 ] || exit 1
[ "$differs" -eq 0 ] || exit 4
