# Atlas, Imoto Figure 5 / Table 1: relative error against the cost of computing it, one row
# per operator and one column per regular order m, the three weights of the operator in each
# panel (line style = weight).  Every weight and operator of a (level, m) unit comes out of one
# fused pass, so the curves of a panel share their abscissae: the bottom axis is the unit's
# neighbour pairs, and the top axis marks, at each unit, its wall time (the whole unit's, not
# apportioned; from the same rows).  The panels share the pairs axis, and the panels of a row
# share the error axis, so the lower envelope over m reads across a row.
# Columns are addressed by name (rel_error, time_s, pairs, operator, weight, m of atlas_imoto.tsv).
load 'figures/style.gp'
set terminal svg size 1100,1250 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/atlas_imoto.tsv'
ops = "interpolant gradient laplacian"
sym = "Π ∇ Δ"
pre = "Pi Grad Lap"
ms = "1 3 5"
set format x '10^{%T}'
set format y '10^{%T}'
set logscale x2
set x2tics font ',9' rotate by 30 left nomirror
set xtics nomirror
set key outside right top font ',10' samplen 3
# Decade-aligned ranges (computed before any range is set: stats applies the current ranges).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
stats f using (column("pairs")) name 'SX' nooutput
xlo = lo(SX_min); xhi = hi(SX_max)
# The top axis of an m: "(time) pairs" of each of its units, as gnuplot's tic list.
units(m) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"m\"]==%s && !s[$c[\"level\"]]++ { printf \"%%s\\\"%%.2g\\\" %%s\", n++ ? \", \" : \"\", $c[\"time_s\"], $c[\"pairs\"] }' '%s'", m, f))
set multiplot layout 3,3 margins 80.0/1100,1 - 120.0/1100,60.0/1250,1 - 110.0/1250 spacing 45.0/1100,135.0/1250 \
    title "Imoto Figure 5 / Table 1: accuracy against cost"
do for [k=1:3] {
  set autoscale xy
  stats rows_named(f, sprintf('$c["operator"]=="%s"', word(ops, k))) using (column("rel_error")) name 'SY' nooutput
  do for [c=1:3] {
    m = word(ms, c)
    set xrange [xlo:xhi]; set x2range [xlo:xhi]
    set yrange [lo(SY_min):hi(SY_max)]
    # Title and top-axis name at fixed heights above the rotated top tic labels.
    unset label
    set label 1 sprintf('%s, m = %s', word(ops, k), m) at graph 0.5, 1.24 center
    set label 2 'wall time of the unit [s]' at graph 0.5, 1.15 center font ',9'
    eval 'set x2tics ('.units(m).')'
    set xlabel (k == 3 ? 'neighbour pairs of the (level, m) unit' : '')
    set ylabel (c == 1 ? 'relative ℓ^∞(Ω) error (max over particles in Ω, Euclidean for ∇)' : '') font ',10'
    if (c == 3) { set key } else { unset key }
    plot for [j=1:3] \
         rows_named(f, sprintf('$c["operator"]=="%s" && $c["weight"]=="%s%d" && $c["m"]==%s', word(ops, k), word(pre, k), j, m)) \
         using (column("pairs")):(column("rel_error")) with linespoints lt j \
         title sprintf('%s%d', word(sym, k), j)
  }
}
unset multiplot
