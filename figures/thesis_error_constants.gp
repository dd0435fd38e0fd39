# The error constant c = e/h^p against level (issue 59), read from gpm store-rates --constants
# (DATADIR/error_constants.tsv): Table 4.4 under each h rule with V_i = dx^2, then the heat
# tables under the identified reading (h15, V_i = dx^2, dt = dt0), as rate_levels' figure lays
# them out.  Per panel the three weights: every stored realization as a point (seed 1 joined by
# a line), the a-priori one-mode constant M of that level as a dashed line, and the levels of
# the documents' published rate circled.  c settling onto M is what the rule calls approaching.
# Drawn at print size: 760 px wide, 14 px text; nine panels in three rows, the key in a strip below.
load 'figures/style.gp'
set terminal svg size 760,640 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/error_constants.tsv'
unset logscale
set logscale y
set format y "%g"
set grid lc rgb '#dddddd'
unset key
unset offsets
w(i) = word('quartic_polynomial piecewise_cubic_polynomial piecewise_quintic_polynomial', i)
wn(i) = word('quartic pw.cubic pw.quintic', i)
base(t, r, th, i) = sprintf('$c["table"]=="%s" && $c["reading"]=="%s" && $c["theta"]=="%s" && $c["weight"]=="%s"', t, r, th, w(i))
sel(t, r, th, i) = rows_named(f, base(t, r, th, i))
seed1(t, r, th, i) = rows_named(f, base(t, r, th, i).' && $c["seed"]=="1"')
doc(t, r, th, i) = rows_named(f, base(t, r, th, i).' && $c["seed"]=="1" && $c["where"]=="document"')
PL = 0.085; PW = 0.255; GX = 0.055; PT = 0.95; PH = 0.195; GY = 0.1
set multiplot
T = '4.4 4.4 4.5 4.5 4.5 4.6 4.6 4.7 4.7'
R = 'h10_cell h15_cell h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact'
TH = 'NA NA 0 0.5 1 0.5 1 0.5 1'
thn(s) = s eq '0' ? '0' : s eq '0.5' ? '½' : '1'
title(t, r, th) = t eq '4.4' ? sprintf('Table 4.4, %s, V_i = Δx^2', r eq 'h10_cell' ? 'h10' : 'h15') : sprintf('Table %s, θ = %s', t, thn(th))
do for [p=1:9] {
  t = word(T, p); r = word(R, p); th = word(TH, p)
  eval panel_at((p - 1) % 3 + 1, (p - 1) / 3 + 1)
  set title title(t, r, th) offset 0,-0.6
  set xlabel (p >= 7 ? 'level k (Δx = 2^{-k})' : '') offset 0,0.4
  set ylabel (p % 3 == 1 ? 'e / h^p' : '') offset 1,0
  set xtics 1 format "%g"
  set xrange [3.6:11.4]
  set autoscale y
  set ytics auto
  plot for [i=1:3] sel(t, r, th, i) using (column("level")):(column("constant")) with points lt i ps 0.7 notitle, \
       for [i=1:3] seed1(t, r, th, i) using (column("level")):(column("constant")) with lines lt i notitle, \
       for [i=1:3] seed1(t, r, th, i) using (column("level")):(column("model")) with lines lt i dt 2 lw 1 notitle, \
       for [i=1:3] doc(t, r, th, i) using (column("level")):(column("constant")) with points pt 6 ps 1.6 lc rgb '#000000' notitle
}
KEY_TOP = 0.08
eval key_strip
set key center center horizontal maxrows 2 box noopaque font ',14' samplen 2.5 spacing 1.0
plot for [i=1:3] NaN with linespoints lt i title wn(i), \
     NaN with lines lt 7 dt 2 lw 1 title 'one-mode model M', \
     NaN with points pt 6 ps 1.6 lc rgb '#000000' title "documents' levels"
unset multiplot
