# The thesis' conjecture (issue 40): the heat tables' two-level rates against the finer level of
# each consecutive pair of stored levels, under the identified reading (h15, V_i = dx^2,
# dt = dt0), read from gpm rate-levels (DATADIR/rate_levels.tsv).  One panel per table and theta
# (Table 4.6's explicit series have no theoretical rate and are left out); per panel the three
# weights (point types and dashes tell them apart), the theory's rate (a thin horizontal line)
# and the published rates at the documents' pair (open circles).  Where the store holds other
# jitter realizations of a pair, its band is drawn as an error bar on the seed-1 point.
# Drawn at print size: 640 px wide, 14 px text; the key in a strip along the bottom.
load 'figures/style.gp'
set terminal svg size 640,1000 dynamic enhanced font 'Helvetica,14' background rgb 'white'
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
sel(t, th, i) = rows_named(f, sprintf('$c["table"]=="%s" && $c["theta"]=="%s" && $c["reading"]=="h15_cell_exact" && $c["weight"]=="%s"', t, th, w(i)))
seltheta(t, th) = rows_named(f, sprintf('$c["table"]=="%s" && $c["theta"]=="%s" && $c["reading"]=="h15_cell_exact"', t, th))
band(x) = x eq 'NA' ? NaN : real(x)
# Seven panels on a 2 x 4 grid, the eighth slot for the key.
PL = 0.11; PW = 0.37; GX = 0.12; PT = 0.96; PH = 0.17; GY = 0.075
set multiplot
T = '4.5 4.5 4.5 4.6 4.6 4.7 4.7'
TH = '0 0.5 1 0.5 1 0.5 1'
thn(s) = s eq '0' ? '0' : s eq '0.5' ? '½' : '1'
do for [p=1:7] {
  t = word(T, p); th = word(TH, p)
  eval panel_at((p - 1) % 2 + 1, (p - 1) / 2 + 1)
  set title sprintf('Table %s, θ = %s', t, thn(th)) offset 0,-0.6
  set xlabel (p >= 6 ? 'finer level k of the pair (Δx = 2^{-k})' : '') offset 0,0.4
  set ylabel (p % 2 == 1 ? 'rate in h' : '') offset 1,0
  set xtics 1
  set xrange [4.6:9.4]
  set autoscale y
  plot for [i=1:3] sel(t, th, i) using (column("level_hi")):(column("rate")) with linespoints lt i notitle, \
       for [i=1:3] sel(t, th, i) using (column("level_hi")):(column("rate")):(band(strcol("band_lo"))):(band(strcol("band_hi"))) \
         with yerrorbars lt i pt 0 notitle, \
       seltheta(t, th) using (column("level_hi")):(column("theoretical")) with lines lt 7 lw 1 notitle, \
       seltheta(t, th) using (column("level_hi")):(strcol("published") eq 'NA' ? NaN : column("published")) \
         with points pt 6 ps 1.4 lc rgb '#000000' notitle
}
# The key.
KEY_TOP = PT - 3 * (PH + GY) - 0.01
eval panel_at(2, 4)
eval key_strip
set offsets 0, 0, 0, 0
set lmargin at screen PL + PW + GX; set rmargin at screen 0.95
set bmargin at screen PT - 3 * (PH + GY) - PH; set tmargin at screen PT - 3 * (PH + GY)
set key center center vertical box noopaque font ',14' samplen 2.5 spacing 1.1 Left reverse
plot for [i=1:3] NaN with linespoints lt i title wn(i), \
     NaN with lines lt 7 lw 1 title 'theory (Theorem 3.7)', \
     NaN with points pt 6 ps 1.4 lc rgb '#000000' title 'published'
unset multiplot
