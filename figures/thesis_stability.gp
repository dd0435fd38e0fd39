# Where the θ-method stops being stable: the measured limit Δt*/h² (from λ_max, confirmed by
# runs at 0.9 and 1.1 Δt*) against the thesis' bound (3.3)/h² (δ = 1), over Δx; one column
# per weight, top row explicit (θ = 0, with Table 4.6's nominal step 0.5h²), bottom row θ = ¼.
# Line style = role (solid: limit, h10 = the printed h; dashed: limit, h15; dotted: bound), colour =
# weight; all panels share both axes.
load 'figures/style.gp'
# Print size: 760 px wide (A4 text width 703 px), 14 px text, nothing below 8 pt; panels placed
# by hand and one key, in a strip below them (line style = role, in black).
W = 760; Hc = 500
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/thesis_stability.tsv'
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
wl(i) = i == 1 ? w1 : i == 2 ? w2 : w3
wn(i) = i == 1 ? 'quartic' : i == 2 ? 'pw. cubic' : 'pw. quintic'
openpt(i) = i == 1 ? 6 : i == 2 ? 4 : 8
sel(i, r) = rows_named(f, sprintf('$c["weight"]=="%s" && $c["h_rule"]=="%s"', wl(i), r))
set logscale x 2
unset logscale y
set xtics ('2^{-4}' 2**-4, '2^{-5}' 2**-5, '2^{-6}' 2**-6, '2^{-7}' 2**-7, '2^{-8}' 2**-8, '2^{-9}' 2**-9)
set format y '%g'
# Coarse levels on the left; a margin of a quarter level on either side.
stats f using (column("dx")) nooutput
set xrange [STATS_max*1.2:STATS_min/1.2]
set yrange [0:0.55]
unset key
set multiplot
PL = 80.0 / W; PR = 1 - 12.0 / W; GX = 12.0 / W; PW = (PR - PL - 2 * GX) / 3
PT = 1 - 40.0 / Hc; PB = 130.0 / Hc; GY = 85.0 / Hc; PH = (PT - PB - GY) / 2
do for [t=1:2] {
  sfx = t == 1 ? '0' : 'q'
  do for [i=1:3] {
    set title sprintf('%s, %s', wn(i), t == 1 ? 'explicit (θ = 0)' : 'θ = 1/4')
    set ylabel (i == 1 ? 'time step / h^2' : '')
    set format y (i == 1 ? '%g' : '')
    set xlabel (t == 2 ? 'particle spacing Δx' : '')
    eval panel_at(i, t)
    if (t == 1) {
      plot sel(i, 'h10') using (column("dx")):(column("limit_over_h2_0")) with linespoints lt i dt 1 notitle, \
           sel(i, 'h15') using (column("dx")):(column("limit_over_h2_0")) with linespoints lt i dt 2 pt openpt(i) notitle, \
           sel(i, 'h10') using (column("dx")):(column("bound_over_h2_0")) with linespoints lt i dt 3 lw 1 pt 1 notitle, \
           0.5 with lines lc rgb '#000000' dt 4 lw 1 notitle
    } else {
      plot sel(i, 'h10') using (column("dx")):(column("limit_over_h2_q")) with linespoints lt i dt 1 notitle, \
           sel(i, 'h15') using (column("dx")):(column("limit_over_h2_q")) with linespoints lt i dt 2 pt openpt(i) notitle, \
           sel(i, 'h10') using (column("dx")):(column("bound_over_h2_q")) with linespoints lt i dt 3 lw 1 pt 1 notitle
    }
  }
}
# The key: the roles, drawn in black, in one strip under the panels.
KEY_TOP = 50.0 / Hc; eval key_strip
set key center center horizontal maxrows 2 samplen 2.5 width -2 box noopaque
plot NaN with linespoints lt 1 dt 1 title 'limit, h10 (printed h)', \
     NaN with linespoints lt 1 dt 2 pt 6 title 'limit, h15', \
     NaN with linespoints lt 1 dt 3 lw 1 pt 1 title 'bound (3.3), δ = 1', \
     NaN with lines lc rgb '#000000' dt 4 lw 1 title 'Table 4.6: 0.5 h^2'
unset multiplot
