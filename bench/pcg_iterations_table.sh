#!/usr/bin/env bash
# The side-by-side table of issue 58, item 1: Table 4.4 (V_i = dx^2, seed 1, tol 1e-10) per h rule,
# weight and level, plain CG's iterations and τ-PCG's.  Plain CG's come from the result store's
# rows (every stored row is plain CG's; results/paper/thesis_table4_4_cellvol.tsv), τ-PCG's from
# bench_pcg's files (given); a level a file lacks is left empty.
#   bash bench/pcg_iterations_table.sh results/bench/pcg_table4_4_*.tsv > results/bench/pcg_iterations_table4_4.tsv
export LC_ALL=C
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: pcg_iterations_table.sh BENCH_PCG_TSV..." >&2; exit 2; }
printf '# program = bench/pcg_iterations_table.sh\n# store = results/paper/thesis_table4_4_cellvol.tsv (plain CG, tol 1e-10)\n'
printf '# tau_from = %s\n' "$*"
printf 'h_rule\tweight\tlevel\tcg_iterations\ttau_iterations\tratio\n'
awk -F'\t' -v OFS='\t' '
  FNR == 1 { hdr = 0 }
  /^#/ { next }
  !hdr { delete c; for (i = 1; i <= NF; i++) c[$i] = i; hdr = 1; store = ("cg_iterations" in c); next }
  store { k = $c["h_rule"] SUBSEP $c["weight"] SUBSEP $c["level"]; cg[k] = $c["cg_iterations"]; keys[k] = 1; next }
  ("volumes" in c) && $c["volumes"] == "cell" && $c["solver"] == "tau" {
    k = $c["h_rule"] SUBSEP $c["weight"] SUBSEP $c["level"]; tau[k] = $c["iterations"]; keys[k] = 1 }
  END {
    for (k in keys) {
      split(k, p, SUBSEP)
      r = (k in cg) && (k in tau) && tau[k] > 0 ? sprintf("%.1f", cg[k] / tau[k]) : ""
      print p[1], p[2], p[3], (k in cg) ? cg[k] : "", (k in tau) ? tau[k] : "", r
    }
  }' results/paper/thesis_table4_4_cellvol.tsv "$@" | sort -t$'\t' -k1,1 -k2,2 -k3,3n
