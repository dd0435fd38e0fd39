# Atlas, Imoto Figure 5 / Table 1: relative error against the cost of computing it, one row
# per operator (named on the error axis) and one column per regular order m (headed over the
# top row), the three weights of the operator in each panel (line style = weight, the same in
# every panel; one legend, in a strip below the panels).  Every weight and operator of a
# (level, m) unit comes out of one fused pass, so the curves of a panel share their abscissae:
# the bottom axis is the unit's neighbour pairs, and the top axis marks, at each unit, its wall
# time (the whole unit's, not apportioned; from the same rows), labelled over the top row (a
# column shares them) and ticked in every row.  The panels share the pairs axis (labelled
# under the bottom row), and the panels of a row share the error axis, so the lower envelope
# over m reads across a row.  Error: relative ℓ^∞(Ω) (max over the particles in Ω; Euclidean
# norm for ∇).
# Columns are addressed by name (rel_error, time_s, pairs, operator, weight, m of atlas_imoto.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing prints
# below 8 pt; panels placed by hand with panel_at.
load 'figures/style.gp'
W = 760; Hc = 900
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/atlas_imoto.tsv'
ops = "interpolant gradient laplacian"
sym = "Π ∇ Δ"
pre = "Pi Grad Lap"
ms = "1 3 5"
set format y '10^{%T}'
set logscale x2
set xtics nomirror 100
unset key
# Decade-aligned ranges (computed before any range is set: stats applies the current ranges).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
stats f using (column("pairs")) name 'SX' nooutput
xlo = lo(SX_min); xhi = hi(SX_max)
# The top axis of an m: "(time in ms) pairs" of each of its units, as gnuplot's tic list.
# With lab = 0 the tics alone, unlabelled (rows below the first).
units(m, lab) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"m\"]==%s && !s[$c[\"level\"]]++ { printf \"%%s\\\"%%s\\\" %%s\", n++ ? \", \" : \"\", %d ? (sprintf(\"%%.2g\", 1000 * $c[\"time_s\"]) + 0) \"\" : \"\", $c[\"pairs\"] }' '%s'", m, lab, f))
set multiplot title "Imoto Figure 5 / Table 1: relative ℓ^∞(Ω) error against cost" font ',15'
PL = 92.0 / W; PR = 1 - 20.0 / W; GX = 40.0 / W; PW = (PR - PL - 2 * GX) / 3
PT = 1 - 140.0 / Hc; GY = 32.0 / Hc; PB = 120.0 / Hc; PH = (PT - PB - 2 * GY) / 3
do for [k=1:3] {
  set autoscale xy
  stats rows_named(f, sprintf('$c["operator"]=="%s"', word(ops, k))) using (column("rel_error")) name 'SY' nooutput
  do for [c=1:3] {
    m = word(ms, c)
    eval panel_at(c, k)
    set xrange [xlo:xhi]; set x2range [xlo:xhi]
    set yrange [lo(SY_min):hi(SY_max)]
    # Column head and top-axis name at fixed heights above the rotated top tic labels (top row).
    unset label
    if (k == 1) {
      set label 1 sprintf('m = %s', m) at graph 0.5, 1.44 center
      set label 2 'wall time of the unit [ms]' at graph 0.5, 1.31 center
    }
    eval 'set x2tics ('.units(m, k == 1).') rotate by 60 left nomirror'
    set format x (k == 3 ? '10^{%T}' : '')
    set xlabel (k == 3 && c == 2 ? 'neighbour pairs of the (level, m) unit' : '') offset 0,0.4
    set format y (c == 1 ? '10^{%T}' : '')
    set ylabel (c == 1 ? sprintf("%s\nrelative error", word(ops, k)) : '')
    plot for [j=1:3] \
         rows_named(f, sprintf('$c["operator"]=="%s" && $c["weight"]=="%s%d" && $c["m"]==%s', word(ops, k), word(pre, k), j, m)) \
         using (column("pairs")):(column("rel_error")) with linespoints lt j notitle
  }
}
# The key: one row under the panels (the line type is the weight's index in every panel).
KEY_TOP = 42.0 / Hc; eval key_strip
set key center center horizontal maxrows 1 samplen 1.5 width -6 box noopaque  # drawn once (an opaque key is drawn twice)
plot for [j=1:3] NaN with linespoints lt j title sprintf('weight %d (Π%d, ∇%d, Δ%d)', j, j, j, j)
unset multiplot
