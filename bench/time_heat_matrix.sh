#!/usr/bin/env bash
# A heat table's whole reading matrix (2 h rules x 2 volumes x 2 time-step rules, every weight,
# theta and paper level) in one thesis_heat run with the default propagator, into a scratch
# folder (never the store): its wall time and peak memory, and per reading the rows, the
# Krylov and stepped series and the largest subspace dimension (issue 39's goal for Table 4.5:
# under 15 minutes).
#
# usage: bench/time_heat_matrix.sh BIN TABLE OUT_TSV [PROPAGATOR]
#   BIN: a thesis_heat binary (a frozen copy, so a rebuild meanwhile does not change it)
export LC_ALL=C
set -eu
if [ $# -lt 3 ]; then echo "usage: bench/time_heat_matrix.sh BIN TABLE OUT_TSV [PROPAGATOR]" >&2; exit 2; fi
bin=$1 table=$2 out=$3 how=${4:-auto}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
load0=$(cut -d" " -f1-3 /proc/loadavg)
/usr/bin/time -f '%e %M' -o "$scratch/time" "$bin" --table "$table" --h-rule h10,h15 --volumes lattice,cell \
  --dt-rule fit,exact --profile paper --propagator "$how" --out "$scratch/m{reading}.tsv" >"$scratch/log" 2>&1
read -r wall rss_kib <"$scratch/time"
tmp=$(mktemp "$out.XXXX")
{
  echo "# Table $table's whole reading matrix in one thesis_heat run (--propagator $how), paper levels"
  echo "# machine = $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); print $2}'), $(nproc) vCPUs; load average before: $load0, after: $(cut -d" " -f1-3 /proc/loadavg)"
  echo "# command = bench/time_heat_matrix.sh BIN $table OUT $how"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "# wall_s = $wall"
  echo "# peak_rss_mib = $((rss_kib / 1024))"
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'reading\trows\tkrylov_series\tstepped_series\tsubspace_max\tseconds_sum\n'
  for f in "$scratch"/m*.tsv; do
    r=$(basename "$f" .tsv); r=${r#m}
    awk -F'\t' -v r="${r:-printed}" -v OFS='\t' '/^#/{next} !h{for(i=1;i<=NF;i++)c[$i]=i; h=1; next}
      { n++; if ($c["propagator"] == "krylov") k++; else s++; if ($c["subspace"] > m) m = $c["subspace"]; t += $c["seconds"] }
      END { print r, n, k + 0, s + 0, m + 0, t }' "$f"
  done
} >"$tmp"
mv "$tmp" "$out"
cat "$out"
