# Covering radius r_c / dx against dx.  Left: plain grid (exact value known); right: jittered
# grids (three seeds, and the cells of particles in Ω for seed 1).  Both panels carry Imoto's
# claimed bound sqrt(2)(1+1/4)/2 and the thesis' range [1.4, 1.8], and share their axes.
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing
# prints below 8 pt; panels placed by hand, the y tick labels on the left panel only, and the
# key in a strip below them: under each panel its own series, the two reference lines that
# both panels carry once (under the left panel).
load 'figures/style.gp'
W = 760; Hc = 520
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/core_voronoi.tsv'
unset logscale y
set format x '2^{%L}'
set logscale x 2
# A margin of a quarter level on either side (points on the frame would be cut in half).
stats f using (column("dx")) name 'DX' nooutput
set xrange [DX_min/1.2:DX_max*1.2]
set xlabel 'Δx' offset 0,0.3
set yrange [0.5:2.0]
unset key
grid1 = rows_named(f, '$c["distribution"]=="grid" && $c["seed"]==1')
jit(s) = rows_named(f, sprintf('$c["distribution"]=="jittered" && $c["seed"]==%d', s))
PL = 62.0 / W; PR = 1 - 14.0 / W; GX = 16.0 / W; PW = (PR - PL - GX) / 2
PT = 1 - 34.0 / Hc; PB = 160.0 / Hc; GY = 0; PH = PT - PB
set multiplot
set title 'plain grid' offset 0,-0.4
set ylabel 'r_c / Δx'
set format y '%g'
eval panel_at(1, 1)
plot grid1 using (column("dx")):(column("r_c_over_dx")) with linespoints lt 1 notitle, \
     grid1 using (column("dx")):(column("r_c_grid_pred")/column("dx")) with lines lt 7 notitle, \
     grid1 using (column("dx")):(column("imoto_bound")/column("dx")) with lines lt 6 notitle, \
     1.4 with lines lt 8 notitle, 1.8 with lines lt 8 notitle
set title 'jittered grid'
set ylabel ''
set format y ''
eval panel_at(2, 1)
plot for [s=1:3] jit(s) using (column("dx")):(column("r_c_over_dx")) with linespoints lt s + 1 notitle, \
     jit(1) using (column("dx")):(column("r_c_omega_over_dx")) with linespoints lt 5 notitle, \
     grid1 using (column("dx")):(column("imoto_bound")/column("dx")) with lines lt 6 notitle, \
     1.4 with lines lt 8 notitle, 1.8 with lines lt 8 notitle
# The key, in a strip under the panels: each panel's series under it, the reference lines of
# both panels once, under the left one.
KEY_TOP = 100.0 / Hc; eval key_strip
set key left center vertical maxrows 4 Left reverse samplen 2.5 nobox noopaque
set lmargin at screen PL; set rmargin at screen PL + PW
plot NaN with linespoints lt 1 title 'measured (plain grid)', \
     NaN with lines lt 7 title 'exact: √2·max(Δx/2, g)/Δx', \
     NaN with lines lt 6 title 'Imoto §5 claim √2(1+1/4)/2', \
     NaN with lines lt 8 title 'thesis Ch. 4 range 1.4–1.8'
set lmargin at screen PL + PW + GX; set rmargin at screen PR
plot for [s=1:3] NaN with linespoints lt s + 1 title sprintf('seed %d', s), \
     NaN with linespoints lt 5 title 'seed 1, cells of particles in Ω'
unset multiplot
