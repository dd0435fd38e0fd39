#!/usr/bin/env bash
# One real heat unit timed both ways (issue 26): Table 4.6 under h15 at one level, one weight,
# theta 0, 1/2, 1 x volumes (A.10) and dx^2 -- six series that share one Laplacian.
#   batched: one thesis_heat run with --volumes lattice,cell (the six series in one block stream);
#   alone:   six runs, one series each (each streams the Laplacian by itself).
# Both write to a scratch folder (never the store); the script then checks that every error
# the two ways give is the same number (to the CG tolerance) and writes one timing table.
#
# usage: bench/time_heat_unit.sh BIN LEVEL OUT_TSV [WEIGHT]
#   BIN: a thesis_heat binary (a frozen copy, so a rebuild meanwhile does not change it)
# Run it on a quiet machine: the two ways are compared by wall time.
export LC_ALL=C
set -eu
bin=$1 level=$2 out=$3 weight=${4:-quartic_polynomial}
scratch=$(mktemp -d)
common=(--table 4.6 --h-rule h15 --dt-rule fit --weights "$weight" --levels "$level" --profile paper)
now() { date +%s.%N; }

load0=$(cut -d" " -f1-3 /proc/loadavg)
t0=$(now)
"$bin" "${common[@]}" --volumes lattice,cell --thetas 0,0.5,1 --out "$scratch/batched{reading}.tsv" >"$scratch/batched.log" 2>&1
t1=$(now)
for vol in lattice cell; do
  for th in 0 0.5 1; do
    "$bin" "${common[@]}" --volumes "$vol" --thetas "$th" --out "$scratch/alone_${vol}_${th}.tsv" >>"$scratch/alone.log" 2>&1
  done
done
t2=$(now)

# The errors, by (volumes, theta, level): the batched files are named by reading, the alone ones by run.
errors() {  # file volumes -> "volumes theta level error" per row, columns addressed by name
  awk -F'\t' -v vol="$2" '/^#/{next} !h{for(i=1;i<=NF;i++)c[$i]=i; h=1; next}
    {print vol, $c["weight"], $c["theta"], $c["level"], $c["rel_error"]}' "$1"
}
{ errors "$scratch/batched_h15.tsv" lattice; errors "$scratch/batched_h15_cellvol.tsv" cell; } | sort >"$scratch/b.txt"
for vol in lattice cell; do for th in 0 0.5 1; do errors "$scratch/alone_${vol}_${th}.tsv" $vol; done; done | sort >"$scratch/a.txt"
maxrel=$(paste -d' ' "$scratch/b.txt" "$scratch/a.txt" | awk '{d=$5-$10; if(d<0)d=-d; r=d/($10<0?-$10:$10); if(r>m)m=r} END{printf "%.3g", m+0}')
series=$(wc -l <"$scratch/b.txt")

tmp=$(mktemp "$out.XXXX")
{
  echo "# One real unit timed both ways (issue 26): Table 4.6 at 2^-$level, h15, $weight weight, theta 0, 1/2, 1 x volumes (A.10) and dx^2 ($series series)"
  echo "# machine = $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); n=$2} /CPU family/{gsub(/ /,"",$2); f=$2} /^Model:/{gsub(/ /,"",$2); m=$2} END{print n " family " f " model " m}'), $(nproc) vCPUs; load average before: $load0, after: $(cut -d" " -f1-3 /proc/loadavg)"
  echo "# command = bench/time_heat_unit.sh BIN $level OUT $weight (batched: one thesis_heat run with --volumes lattice,cell; alone: six runs, one series each)"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "# errors_max_rel_diff = $maxrel (batched against alone, every series)"
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'way\twall_s\tseries\n'
  awk -v a="$t0" -v b="$t1" -v s="$series" 'BEGIN{printf "batched\t%.1f\t%d\n", b-a, s}'
  awk -v a="$t1" -v b="$t2" -v s="$series" 'BEGIN{printf "alone\t%.1f\t%d\n", b-a, s}'
} >"$tmp"
mv "$tmp" "$out"
cat "$out"
rm -rf "$scratch"
