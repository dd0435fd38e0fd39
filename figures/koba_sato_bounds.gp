# Koba & Sato, Theorems 1.3-1.6 on Voronoi cells: the measured error of each operator at a_k
# (points) and the theorem's right-hand side with the constants computed from the cells
# (lines) against C* = h/r_sigma; one row per operator.  Site 0 of the first tessellation
# (level 8, seed 1), lambda = 1/2.  Left column: the test function sin 2π(x+y) with the step
# weight of Section 7 and the Lipschitz weight Pi1 (w = 3/pi (1 - r/h)), and Corollary 7.1's
# formula (step weight) at the measured r_sigma; right column: the plane wave with the step
# weight.  The two panels of a row share their axes (y tick labels on the left panel only).
# Columns are addressed by name (koba_sato_bounds.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing
# prints below 8 pt; panels placed by hand, and the key in a strip below them, under each
# column the series of that column.
load 'figures/style.gp'
W = 760; Hc = 1130
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/koba_sato_bounds.tsv'
sel(w, fn) = rows_named(f, sprintf('$c["level"]==8 && $c["seed"]==1 && $c["site"]==0 && $c["lambda"]==0.5 && $c["weight"]=="%s" && $c["func"]=="%s"', w, fn))
all = rows_named(f, '$c["level"]==8 && $c["seed"]==1 && $c["site"]==0 && $c["lambda"]==0.5 && ($c["weight"]=="step" || ($c["weight"]=="Pi1" && $c["func"]=="sin2pi")) && ($c["func"]=="sin2pi" || $c["func"]=="wave")')
set logscale x 2
set format x '2^{%L}'
set xrange [1.8:70]
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
unset key
# Panel boxes (screen fractions): columns = test functions, rows = operators.
PL = 80.0 / W; PR = 1 - 14.0 / W; GX = 16.0 / W; PW = (PR - PL - GX) / 2
PT = 1 - 78.0 / Hc; PB = 135.0 / Hc; GY = 72.0 / Hc; PH = (PT - PB - 3 * GY) / 4
set multiplot title 'Koba–Sato Theorems 1.3–1.6 at one particle: error (points) and bound (lines)' font ',15'
do for [p = 1:4] {
  o = word('pi grad lap box', p)
  e = 'err_'.o; b = 'bound_'.o; c = 'cor_'.o   # error, bound, Corollary 7.1 formula
  name = (p == 1 ? 'interpolant Π̃_h (Theorem 1.3)' : p == 2 ? 'gradient ∇̃_h (Theorem 1.4)' : p == 3 ? 'Laplacian Δ̃_h (Theorem 1.5)' : 'Laplacian □̃_h (Theorem 1.6)')
  # One error axis per row, from every error, bound and formula drawn in it.
  set autoscale y
  stats all using (column(e)) name 'SE' nooutput
  stats all using (column(b)) name 'SB' nooutput
  stats sel('step', 'sin2pi') using (column(c)) name 'SC' nooutput
  ymin = SE_min < SB_min ? SE_min : SB_min; ymin = ymin < SC_min ? ymin : SC_min
  ymax = SE_max > SB_max ? SE_max : SB_max; ymax = ymax > SC_max ? ymax : SC_max
  set yrange [lo(ymin):hi(ymax)]
  if (p == 4) { set xlabel 'C* = h / r_σ' offset 0,0.3 } else { unset xlabel }
  set ylabel 'error, bound'
  set format y '10^{%L}'
  set title name.', sin 2π(x+y)' offset 0,-0.2
  eval panel_at(1, p)
  plot sel('step', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 1 notitle, \
       sel('step', 'sin2pi') using (column("C_star")):(column(e)) with points lt 1 notitle, \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 3 notitle, \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(e)) with points lt 3 notitle, \
       sel('step', 'sin2pi') using (column("C_star")):(column(c)) with lines lt 7 notitle
  set title name.', plane wave'
  set ylabel ''
  set format y ''
  eval panel_at(2, p)
  plot sel('step', 'wave') using (column("C_star")):(column(b)) with lines lt 2 notitle, \
       sel('step', 'wave') using (column("C_star")):(column(e)) with points lt 2 notitle
}
# The key, in a strip under the panels: under each column the series drawn in it.
KEY_TOP = 72.0 / Hc; eval key_strip
set key left center vertical maxrows 3 Left reverse samplen 2.5 width -4 nobox noopaque
set lmargin at screen PL; set rmargin at screen PL + PW
plot NaN with lines lt 1 title 'bound (step)', \
     NaN with points lt 1 title 'error (step)', \
     NaN with lines lt 3 title 'bound (Π1)', \
     NaN with points lt 3 title 'error (Π1)', \
     NaN with lines lt 7 title 'Cor. 7.1 (step)'
set lmargin at screen PL + PW + GX; set rmargin at screen PR
plot NaN with lines lt 2 title 'bound (step, wave)', \
     NaN with points lt 2 title 'error (step, wave)'
unset multiplot
