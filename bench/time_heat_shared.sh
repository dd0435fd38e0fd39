#!/usr/bin/env bash
# Tables 4.5-4.7 at one level, h rule, volumes, time-step rule and weight (issue 58, item 2):
# each table alone (three thesis_heat runs), then the three in one run, which builds the
# Laplacian and the Krylov subspace once; into a scratch folder, never the store.  The shared
# run verifies the three files the tables wrote alone (store --verify: every number and the
# subspace compared), so the timing holds only if its rows equal theirs; the table says so.
#
# usage: bench/time_heat_shared.sh [--two-at-a-time] BIN LEVEL H_RULE VOLUMES DT_RULE WEIGHT PROPAGATOR OUT_TSV
#   BIN: a thesis_heat binary (a frozen copy); PROPAGATOR: auto (each series the cheaper
#   way, as the store's runs), krylov (every series through the subspace) or stepped.
# Wall times of runs one after another on this machine: the load average before and after
# each run is recorded beside it.
#   --two-at-a-time: for levels where the four runs one after another outlast a session, the
#   runs go in two pairs on two cores (4.5 beside 4.6, then 4.7 beside the shared run), each
#   pair under the same load.  The shared run then cannot verify a file still being written:
#   it writes its own files, and equal_rows compares them with the alone runs' row by row
#   (every column but the timing ones, as printed).
export LC_ALL=C
set -eu
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/.." && pwd)/tables/census_lib.sh"
usage="usage: bench/time_heat_shared.sh [--two-at-a-time] BIN LEVEL H_RULE VOLUMES DT_RULE WEIGHT PROPAGATOR OUT_TSV"
pairs=0
if [ "${1:-}" = --two-at-a-time ]; then pairs=1; shift; fi
if [ $# -ne 8 ]; then
  echo "$usage" >&2
  exit 2
fi
bin=$1 level=$2 rule=$3 volumes=$4 dt=$5 weight=$6 how=$7 out=$8
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
common=(--h-rule "$rule" --volumes "$volumes" --dt-rule "$dt" --weights "$weight" --levels "$level"
        --profile paper --propagator "$how")
now() { date +%s.%N; }
load() { cut -d" " -f1-3 /proc/loadavg; }
# The distinct values of column $1 over the rows of the files that follow, comma-separated.
distinct() {
  local col=$1; shift
  awk -F'\t' -v col="$col" '/^#/{next} !(FILENAME in h){for(i=1;i<=NF;i++)c[$i]=i; h[FILENAME]; next} {print $c[col]}' "$@" |
    sort -u | paste -sd,
}
# The subspace sizes a run's rows took (0: stepped).
sizes() { distinct subspace "$@" | tr , '\n' | sort -n | paste -sd,; }
# One run timed: its row (tables, wall_s, rows, subspace, equal_rows, loads) into $scratch/$1.row.
timed() {
  local name=$1; shift
  local l0 t0 t1 l1 rc=0
  l0=$(load); t0=$(now)
  "$bin" "$@" >"$scratch/$name.log" 2>&1 || rc=$?
  t1=$(now); l1=$(load)
  echo "$rc" >"$scratch/$name.rc"
  printf '%s\t%s\t%s\t%s\n' "$name" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b-a}')" "$l0" "$l1" >"$scratch/$name.row"
}
alone() { timed "$1" --table "$1" "${common[@]}" --out "$scratch/thesis_table${1/./_}.tsv"; }
# Stop at the first failed alone run, before the next (hour-long) runs start.
succeeded() {
  local name
  for name; do
    [ "$(cat "$scratch/$name.rc")" = 0 ] || { echo "time_heat_shared.sh: table $name alone failed (exit $(cat "$scratch/$name.rc"))" >&2; tail -3 "$scratch/$name.log" >&2; exit 1; }
  done
}
all=4.5,4.6,4.7
# The rows of a heat file without the columns that time a run, sorted: equal output, equal rows.
numbers() { data_rows "$1" '^(seconds|s_per_step|made_on|checked|seal)$' | sort; }
if [ $pairs -eq 0 ]; then
  for table in 4.5 4.6 4.7; do alone "$table"; succeeded "$table"; done
  # A difference (exit 4) is a measurement too: the table is written, then the script fails.
  timed $all --table $all "${common[@]}" --out "$scratch/thesis_table{table}.tsv" --verify
  equal=$(grep -c 'max relative difference 0 (tolerance' "$scratch/$all.log" || true)
else
  alone 4.5 & alone 4.6 & wait
  succeeded 4.5 4.6
  mkdir "$scratch/shared"
  alone 4.7 &
  timed $all --table $all "${common[@]}" --out "$scratch/shared/thesis_table{table}.tsv" &
  wait
  succeeded 4.7
  equal=0
  for f in "$scratch"/thesis_table4_?.tsv; do
    [ -f "$scratch/shared/${f##*/}" ] && cmp -s <(numbers "$f") <(numbers "$scratch/shared/${f##*/}") && equal=$((equal + 1))
  done
fi
rc=$(cat "$scratch/$all.rc")
[ "$rc" -eq 0 ] || [ "$rc" -eq 4 ] || { echo "time_heat_shared.sh: the shared run failed (exit $rc)" >&2; tail -3 "$scratch/$all.log" >&2; exit 1; }
shared_files=("$scratch"/thesis_table4_?.tsv)
[ $pairs -eq 0 ] || shared_files=("$scratch"/shared/thesis_table4_?.tsv)
rows=()
for name in 4.5 4.6 4.7 $all; do
  IFS=$'\t' read -r _ wall l0 l1 <"$scratch/$name.row"
  if [ "$name" = $all ]; then
    rows+=("$name	$wall	NA	$(sizes "${shared_files[@]}")	$equal of 3	$l0	$l1")
  else
    f=$scratch/thesis_table${name/./_}.tsv
    rows+=("$name	$wall	$(grep -vc '^#' "$f" | awk '{print $1-1}')	$(sizes "$f")	NA	$l0	$l1")
  fi
done
how_run="one after another, one thread each"
[ $pairs -eq 0 ] || how_run="two at a time on two cores (4.5 beside 4.6, then 4.7 beside the shared run), one thread each"

tmp=$(mktemp "$out.XXXX")
{
  echo "# Tables 4.5-4.7 alone and in one run sharing the Laplacian and the Krylov subspace (issue 58, item 2): 2^-$level, $rule, volumes $volumes, dt $dt, $weight weight, propagator $how"
  echo "# machine = $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); n=$2} /CPU family/{gsub(/ /,"",$2); f=$2} /^Model:/{gsub(/ /,"",$2); m=$2} END{print n " family " f " model " m}'), $(nproc --all) vCPUs, OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}"
  echo "# runs = $how_run"
  echo "# command = bench/time_heat_shared.sh $([ $pairs -eq 0 ] || echo '--two-at-a-time ')BIN $level $rule $volumes $dt $weight $how OUT"
  echo "# code = $(distinct code "$scratch"/thesis_table4_?.tsv "${shared_files[@]}")"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  if [ $pairs -eq 0 ]; then
    echo "# note = equal_rows: the shared run's --verify of each table's own file, largest relative difference exactly 0 (every number and the subspace size)"
  else
    echo "# note = equal_rows: the shared run's files against the alone runs', every column but seconds, s_per_step, made_on, checked and seal equal as printed"
  fi
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'tables\twall_s\trows\tsubspace\tequal_rows\tload_before\tload_after\n'
  printf '%s\n' "${rows[@]}"
} >"$tmp"
mv "$tmp" "$out"
cat "$out"
awk -F'\t' -v all=$all '/^#/||/^tables/{next} $1 != all {s += $2; if ($2 > m) m = $2} $1 == all {x = $2}
  END {printf "shared / slowest alone = %.2f, shared / sum alone = %.2f\n", x / m, x / s}' "$out"
[ "$equal" = 3 ] || { echo "time_heat_shared.sh: $equal of 3 files equal bit for bit (the shared run: exit $rc)" >&2; exit 4; }
