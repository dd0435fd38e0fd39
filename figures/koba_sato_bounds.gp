# Koba & Sato, Theorems 1.3-1.6 on Voronoi cells: the measured error of each operator at a_k
# (points) and the theorem's right-hand side with the constants computed from the cells
# (lines) against C* = h/r_sigma; one row per operator.  Site 0 of the first tessellation
# (level 8, seed 1), lambda = 1/2.  Left column: the test function sin 2π(x+y) with the step
# weight of Section 7 and the Lipschitz weight Pi1 (w = 3/pi (1 - r/h)), and Corollary 7.1's
# formula (step weight) at the measured r_sigma; right column: the plane wave with the step
# weight.  The two panels of a row share their axes.  Columns are addressed by name
# (koba_sato_bounds.tsv).
load 'figures/style.gp'
set terminal svg size 960,1250 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/koba_sato_bounds.tsv'
sel(w, fn) = rows_named(f, sprintf('$c["level"]==8 && $c["seed"]==1 && $c["site"]==0 && $c["lambda"]==0.5 && $c["weight"]=="%s" && $c["func"]=="%s"', w, fn))
all = rows_named(f, '$c["level"]==8 && $c["seed"]==1 && $c["site"]==0 && $c["lambda"]==0.5 && ($c["weight"]=="step" || ($c["weight"]=="Pi1" && $c["func"]=="sin2pi")) && ($c["func"]=="sin2pi" || $c["func"]=="wave")')
set logscale x 2
set format x '2^{%L}'
set xrange [1.8:70]
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
set key box Left reverse font ',10' samplen 2 width -2
set multiplot layout 4,2 margins 0.09,0.98,0.12,0.95 spacing 0.08,0.06 \
    title 'Koba–Sato Theorems 1.3–1.6 at one particle: error (points) and bound (lines)'
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
  set xlabel (p == 4 ? 'C* = h / r_σ' : '')
  set ylabel 'error, bound'
  set title name.', sin 2π(x+y)'
  if (p < 4) { unset key } else { set key at screen 0.30,0.055 center vertical maxrows 3 }
  plot sel('step', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 1 title 'bound (step)', \
       sel('step', 'sin2pi') using (column("C_star")):(column(e)) with points lt 1 title 'error (step)', \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 3 title 'bound (Π1)', \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(e)) with points lt 3 title 'error (Π1)', \
       sel('step', 'sin2pi') using (column("C_star")):(column(c)) with lines lt 7 title 'Cor. 7.1 (step)'
  set title name.', plane wave'
  set ylabel ''
  if (p < 4) { unset key } else { set key at screen 0.77,0.055 center vertical maxrows 3 }
  plot sel('step', 'wave') using (column("C_star")):(column(b)) with lines lt 2 title 'bound (step, wave)', \
       sel('step', 'wave') using (column("C_star")):(column(e)) with points lt 2 title 'error (step, wave)'
}
unset multiplot
