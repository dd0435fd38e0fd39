# Atlas, imoto Figure 5 / Table 1: relative error against the cost of computing it.
# Left: wall time of the (level, m) unit — one fused pass computes all nine weights and the
# three operators, so all weights of a unit share one time (not apportioned).  Right: the
# unit's neighbour pairs.  Dash pattern = weight, point type = regular order m.
# Columns of atlas_imoto.tsv: 3 level, 4 rel_error, 5 time_s, 6 pairs, 7 operator, 8 weight, 9 m.
load 'figures/style.gp'
set terminal svg size 1100,1150 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
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
         rows(f, sprintf('$7=="%s" && $8=="%s%d" && $9==%s', word(ops, k), word(pre, k), j, m)) \
         using (c == 1 ? $5 : $6):4 with linespoints lt j pt mpt(m + 0) \
         title sprintf('%s%d, m = %s', word(sym, k), j, m)
  }
}
unset multiplot
