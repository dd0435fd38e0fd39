#!/usr/bin/env bash
# Tables 4.5-4.7 at one level, h rule, volumes, time-step rule and weight (issue 58, item 2):
# each table alone (three thesis_heat runs), then the three in one run, which builds the
# Laplacian and the Krylov subspace once; into a scratch folder, never the store.  The shared
# run verifies the three files the tables wrote alone (store --verify: every number and the
# subspace compared), so the timing holds only if its rows equal theirs; the table says so.
#
# usage: bench/time_heat_shared.sh BIN LEVEL H_RULE VOLUMES DT_RULE WEIGHT PROPAGATOR OUT_TSV
#   BIN: a thesis_heat binary (a frozen copy); PROPAGATOR: auto (each series the cheaper
#   way, as the store's runs), krylov (every series through the subspace) or stepped.
# Wall times of runs one after another on this machine: the load average before and after
# each run is recorded beside it.
export LC_ALL=C
set -eu
if [ $# -ne 8 ]; then
  echo "usage: bench/time_heat_shared.sh BIN LEVEL H_RULE VOLUMES DT_RULE WEIGHT PROPAGATOR OUT_TSV" >&2
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
rows=()
for table in 4.5 4.6 4.7; do
  f=$scratch/thesis_table${table/./_}.tsv
  l0=$(load); t0=$(now)
  "$bin" --table "$table" "${common[@]}" --out "$f" >"$scratch/$table.log" 2>&1
  t1=$(now); l1=$(load)
  rows+=("$table	$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b-a}')	$(grep -vc '^#' "$f" | awk '{print $1-1}')	$(sizes "$f")	NA	$l0	$l1")
done
l0=$(load); t0=$(now)
# A difference (exit 4) is a measurement too: the table is written, then the script fails.
rc=0
"$bin" --table 4.5,4.6,4.7 "${common[@]}" --out "$scratch/thesis_table{table}.tsv" --verify >"$scratch/shared.log" 2>&1 || rc=$?
t1=$(now); l1=$(load)
[ $rc -eq 0 ] || [ $rc -eq 4 ] || { echo "time_heat_shared.sh: the shared run failed (exit $rc)" >&2; tail -3 "$scratch/shared.log" >&2; exit 1; }
equal=$(grep -c 'max relative difference 0 (tolerance' "$scratch/shared.log" || true)
rows+=("4.5,4.6,4.7	$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b-a}')	NA	$(sizes "$scratch"/thesis_table4_?.tsv)	$equal of 3	$l0	$l1")

tmp=$(mktemp "$out.XXXX")
{
  echo "# Tables 4.5-4.7 alone and in one run sharing the Laplacian and the Krylov subspace (issue 58, item 2): 2^-$level, $rule, volumes $volumes, dt $dt, $weight weight, propagator $how"
  echo "# machine = $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); n=$2} /CPU family/{gsub(/ /,"",$2); f=$2} /^Model:/{gsub(/ /,"",$2); m=$2} END{print n " family " f " model " m}'), $(nproc --all) vCPUs, OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}"
  echo "# command = bench/time_heat_shared.sh BIN $level $rule $volumes $dt $weight $how OUT"
  echo "# code = $(distinct code "$scratch"/thesis_table4_?.tsv)"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "# note = equal_rows: the shared run's --verify of each table's own file, largest relative difference exactly 0 (every number and the subspace size)"
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'tables\twall_s\trows\tsubspace\tequal_rows\tload_before\tload_after\n'
  printf '%s\n' "${rows[@]}"
} >"$tmp"
mv "$tmp" "$out"
cat "$out"
awk -F'\t' '/^#/||/^tables/{next} $1 != "4.5,4.6,4.7" {s += $2; if ($2 > m) m = $2} $1 == "4.5,4.6,4.7" {x = $2}
  END {printf "shared / slowest alone = %.2f, shared / sum alone = %.2f\n", x / m, x / s}' "$out"
[ "$equal" = 3 ] || { echo "time_heat_shared.sh: $equal of 3 files equal bit for bit (the shared run's verify: exit $rc)" >&2; exit 4; }
