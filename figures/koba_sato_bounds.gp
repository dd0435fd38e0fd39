# Koba & Sato, Theorems 1.3-1.6 on Voronoi cells: the measured error of each operator at a_k
# (points) and the theorem's right-hand side with the constants computed from the cells
# (lines) against C* = h/r_sigma; one panel per operator.  Site 0 of the first tessellation
# (level 8, seed 1), lambda = 1/2; the step weight of Section 7 for two test functions and
# the Lipschitz weight Pi1 (w = 3/pi (1 - r/h)) for one; dashed: Corollary 7.1's formula
# (step weight) at the measured r_sigma.  Columns are addressed by name (koba_sato_bounds.tsv).
load 'figures/style.gp'
set terminal svg size 960,760 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/koba_sato_bounds.tsv'
sel(w, fn) = rows_named(f, sprintf('$c["level"]==8 && $c["seed"]==1 && $c["site"]==0 && $c["lambda"]==0.5 && $c["weight"]=="%s" && $c["func"]=="%s"', w, fn))
set logscale x 2
set format x '2^{%L}'
set xlabel 'C* = h / r_σ'
set xrange [1.8:70]
set multiplot layout 2,2 margins 0.08,0.98,0.2,0.96 spacing 0.09,0.1
do for [p = 1:4] {
  o = word('pi grad lap box', p)
  e = 'err_'.o; b = 'bound_'.o; c = 'cor_'.o   # error, bound, Corollary 7.1 formula
  set title (p == 1 ? 'interpolant Π̃_h (Theorem 1.3)' : p == 2 ? 'gradient ∇̃_h (Theorem 1.4)' : p == 3 ? 'Laplacian Δ̃_h (Theorem 1.5)' : 'Laplacian □̃_h (Theorem 1.6)')
  set ylabel 'error, bound'
  if (p < 4) { unset key } else { set key at screen 0.5,0.07 center vertical maxrows 2 box Left reverse font ',9' samplen 1.5 width -4 }
  plot sel('step', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 1 title 'bound (step, sin2pi)', \
       sel('step', 'sin2pi') using (column("C_star")):(column(e)) with points lt 1 title 'error (step, sin2pi)', \
       sel('step', 'wave') using (column("C_star")):(column(b)) with lines lt 2 title 'bound (step, wave)', \
       sel('step', 'wave') using (column("C_star")):(column(e)) with points lt 2 title 'error (step, wave)', \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(b)) with lines lt 3 title 'bound (Π1, sin2pi)', \
       sel('Pi1', 'sin2pi') using (column("C_star")):(column(e)) with points lt 3 title 'error (Π1, sin2pi)', \
       sel('step', 'sin2pi') using (column("C_star")):(column(c)) with lines lt 7 title 'Cor. 7.1 (step, sin2pi)'
}
unset multiplot
