#!/usr/bin/env bash
# One real heat unit timed both ways (issue 39): a table's series of one level, h rule and
# weight (every θ of the table, volumes (A.10), dt = T/K) run by the stepper and by the Krylov
# propagator (src/gpm/solvers/heat_krylov.hpp), each in one thesis_heat run into a scratch
# folder (never the store).  The script compares the errors of the two runs and writes one
# timing table: wall time per way, the ratio, K, the subspace dimension m and the products.
#
# usage: bench/time_heat_propagator.sh BIN TABLE LEVEL H_RULE OUT_TSV [WEIGHT]
#   BIN: a thesis_heat binary (a frozen copy, so a rebuild meanwhile does not change it)
# The two ways are compared by wall time: the load average before and after each is recorded.
export LC_ALL=C
set -eu
if [ $# -lt 5 ]; then
  echo "usage: bench/time_heat_propagator.sh BIN TABLE LEVEL H_RULE OUT_TSV [WEIGHT]" >&2
  exit 2
fi
bin=$1 table=$2 level=$3 rule=$4 out=$5 weight=${6:-quartic_polynomial}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
common=(--table "$table" --h-rule "$rule" --weights "$weight" --levels "$level" --profile paper)
now() { date +%s.%N; }
load() { cut -d" " -f1-3 /proc/loadavg; }

declare -A wall before after
for way in krylov stepped; do
  before[$way]=$(load)
  t0=$(now)
  "$bin" "${common[@]}" --propagator "$way" --out "$scratch/$way.tsv" >"$scratch/$way.log" 2>&1
  t1=$(now)
  after[$way]=$(load)
  wall[$way]=$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b-a}')
done

# Per series (θ): the two errors, K, m and the products, columns addressed by name.
rows() {
  awk -F'\t' '/^#/{next} !h{for(i=1;i<=NF;i++)c[$i]=i; h=1; next}
    {print $c["theta"], $c["K"], $c["subspace"], $c["rel_error"], $c["rel_error_max"], $c["cg_mean_iterations"]}' "$1"
}
paste -d' ' <(rows "$scratch/stepped.tsv" | sort) <(rows "$scratch/krylov.tsv" | sort) >"$scratch/both.txt"
series=$(wc -l <"$scratch/both.txt")

tmp=$(mktemp "$out.XXXX")
{
  echo "# One real unit timed both ways (issue 39): Table $table at 2^-$level, $rule, $weight weight, every theta of the table, volumes (A.10), dt = T/K ($series series)"
  echo "# machine = $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); n=$2} /CPU family/{gsub(/ /,"",$2); f=$2} /^Model:/{gsub(/ /,"",$2); m=$2} END{print n " family " f " model " m}'), $(nproc) vCPUs"
  echo "# load = krylov: before ${before[krylov]}, after ${after[krylov]}; stepped: before ${before[stepped]}, after ${after[stepped]}"
  echo "# command = bench/time_heat_propagator.sh BIN $table $level $rule OUT $weight"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "# note = stepped: CG to 1e-10 per implicit step (the store's setting); rel_diff: |krylov - stepped| / stepped of the error (4.2)"
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'theta\tK\tsubspace\tcg_mean_iterations\tstepped_products\tkrylov_products\trel_error_stepped\trel_error_krylov\trel_diff\trel_diff_max\tstepped_wall_s\tkrylov_wall_s\tspeedup\n'
  awk -v OFS='\t' -v s="${wall[stepped]}" -v k="${wall[krylov]}" -v n="$series" '
    function rel(a, b) { d = a - b; if (d < 0) d = -d; return d / (b < 0 ? -b : b) }
    { sp = $2 * ($1 > 0 ? 1 + $6 : 1)
      print $1, $2, $9, $6, sp, $9 / n, $4, $10, rel($10, $4), rel($11, $5), s, k, s / k }' "$scratch/both.txt"
} >"$tmp"
mv "$tmp" "$out"
cat "$out"
