# The thesis' conjecture (issue 40): two-level rates against the finer level of each
# consecutive pair of stored levels, read from gpm rate-levels (DATADIR/rate_levels.tsv).
# Panels: Table 4.4 (Poisson) under each h rule with V_i = dx^2, then the heat tables under the
# identified reading (h15, V_i = dx^2, dt = dt0), one per table and theta (Table 4.6's explicit
# series have no theoretical rate and are left out).  Per panel the three weights (point types
# and dashes tell them apart), the theory's rate (a thin horizontal line) and the published
# rates at the documents' pair (open circles).  Where the store holds other jitter realizations
# of a pair, its band is drawn as an error bar on the seed-1 point; a pair that only one
# realization holds, at or past the documents' pair, is marked by a cross (its rate is seed 1's alone).
# Drawn at print size: 640 px wide, 14 px text; the key in the last slot of the grid.
load 'figures/style.gp'
set terminal svg size 640,1120 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/rate_levels.tsv'
unset logscale
set format y '%g'
set grid lc rgb '#dddddd'
unset key
# Room above and below the data, so that the theory's line is never on the frame.
set offsets 0, 0, graph 0.08, graph 0.08
w(i) = word('quartic_polynomial piecewise_cubic_polynomial piecewise_quintic_polynomial', i)
wn(i) = word('quartic pw.cubic pw.quintic', i)
sel(t, r, th, i) = rows_named(f, sprintf('$c["table"]=="%s" && $c["reading"]=="%s" && $c["theta"]=="%s" && $c["weight"]=="%s"', t, r, th, w(i)))
# The pairs whose band is stored (other realizations hold both levels).
selband(t, r, th, i) = rows_named(f, sprintf('$c["table"]=="%s" && $c["reading"]=="%s" && $c["theta"]=="%s" && $c["weight"]=="%s" && $c["band_lo"]!="NA"', t, r, th, w(i)))
# The pairs only one realization holds.
selone(t, r, th, i) = rows_named(f, sprintf('$c["table"]=="%s" && $c["reading"]=="%s" && $c["theta"]=="%s" && $c["weight"]=="%s" && $c["seeds"]=="1" && $c["where"]!="coarser"', t, r, th, w(i)))
seltheta(t, r, th) = rows_named(f, sprintf('$c["table"]=="%s" && $c["reading"]=="%s" && $c["theta"]=="%s"', t, r, th))
# Nine panels on a 2 x 5 grid, the tenth slot for the key; 1120 px tall, so that the page's
# largest figure height (232 mm) prints its text at 8 pt or more.
PL = 0.11; PW = 0.37; GX = 0.12; PT = 0.968; PH = 0.1321; GY = 0.0625
set multiplot
T = '4.4 4.4 4.5 4.5 4.5 4.6 4.6 4.7 4.7'
R = 'h10_cell h15_cell h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact h15_cell_exact'
TH = 'NA NA 0 0.5 1 0.5 1 0.5 1'
thn(s) = s eq '0' ? '0' : s eq '0.5' ? '½' : '1'
title(t, r, th) = t eq '4.4' ? sprintf('Table 4.4, %s, V_i = Δx^2', r eq 'h10_cell' ? 'h10' : 'h15') : sprintf('Table %s, θ = %s', t, thn(th))
do for [p=1:9] {
  t = word(T, p); r = word(R, p); th = word(TH, p)
  eval panel_at((p - 1) % 2 + 1, (p - 1) / 2 + 1)
  set title title(t, r, th) offset 0,-0.6
  set xlabel (p >= 8 ? 'finer level k of the pair (Δx = 2^{-k})' : '') offset 0,0.4
  set ylabel (p % 2 == 1 ? 'rate in h' : '') offset 1,0
  set xtics 1
  set xrange [4.6:10.4]
  set autoscale y
  plot for [i=1:3] sel(t, r, th, i) using (column("level_hi")):(column("rate")) with linespoints lt i notitle, \
       for [i=1:3] selband(t, r, th, i) using (column("level_hi")):(column("rate")):(column("band_lo")):(column("band_hi")) \
         with yerrorbars lt i pt 0 notitle, \
       for [i=1:3] selone(t, r, th, i) using (column("level_hi")):(column("rate")) with points pt 2 ps 1.4 lc rgb '#000000' notitle, \
       seltheta(t, r, th) using (column("level_hi")):(column("theoretical")) with lines lt 7 lw 1 notitle, \
       seltheta(t, r, th) using (column("level_hi")):(strcol("published") eq 'NA' ? NaN : column("published")) \
         with points pt 6 ps 1.4 lc rgb '#000000' notitle
}
# The key.
KEY_TOP = PT - 4 * (PH + GY) - 0.01
eval panel_at(2, 5)
eval key_strip
set offsets 0, 0, 0, 0
set lmargin at screen PL + PW + GX; set rmargin at screen 0.95
set bmargin at screen PT - 4 * (PH + GY) - PH; set tmargin at screen PT - 4 * (PH + GY)
set key center center vertical box noopaque font ',14' samplen 2.5 spacing 1.1 Left reverse
plot for [i=1:3] NaN with linespoints lt i title wn(i), \
     NaN with lines lt 7 lw 1 title 'theory (Thm 2.1, 3.7)', \
     NaN with points pt 6 ps 1.4 lc rgb '#000000' title 'published', \
     NaN with points pt 2 ps 1.4 lc rgb '#000000' title 'one realization'
unset multiplot
