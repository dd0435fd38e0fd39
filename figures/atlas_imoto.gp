# Atlas, imoto Figure 5 / Table 1: relative error against the cost of computing it.
# Left: wall time of the (level, m) unit — one fused pass computes all nine weights and the
# three operators, so all weights of a unit share one time (not apportioned).  Right: the
# unit's neighbour pairs.  Dash pattern = weight, point type = regular order m.
# Columns are addressed by name (rel_error, time_s, pairs, operator, weight, m of atlas_imoto.tsv).
load 'figures/style.gp'
set terminal svg size 1100,1150 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/atlas_imoto.tsv'
ops = "interpolant gradient laplacian"
sym = "Π ∇ Δ"
pre = "Pi Grad Lap"
mpt(m) = m == 1 ? 6 : m == 3 ? 4 : 8
set format x '10^{%T}'
set format y '10^{%T}'
set ylabel 'relative ℓ^∞(Ω) error (max over particles in Ω, Euclidean for ∇)'
set key outside right font ',9' samplen 2.5
set multiplot layout 3,2
do for [k=1:3] {
  do for [c=1:2] {
    set title sprintf('%s: error against %s', word(ops, k), c == 1 ? 'wall time' : 'pair interactions')
    set xlabel (c == 1 ? 'wall time of the (level, m) unit [s]' : 'neighbour pairs of the unit')
    if (c == 1) { unset key } else { set key }
    plot for [j=1:3] for [m in "1 3 5"] \
         rows_named(f, sprintf('$c["operator"]=="%s" && $c["weight"]=="%s%d" && $c["m"]==%s', word(ops, k), word(pre, k), j, m)) \
         using (column(c == 1 ? "time_s" : "pairs")):(column("rel_error")) with linespoints lt j pt mpt(m + 0) \
         title sprintf('%s%d, m = %s', word(sym, k), j, m)
  }
}
unset multiplot
