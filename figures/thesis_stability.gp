# Where the θ-method stops being stable: the measured limit Δt*/h² (from λ_max, confirmed by
# runs at 0.9 and 1.1 Δt*) against the thesis' bound (3.3)/h² (δ = 1), per weight, over Δx.
# Left: explicit (θ = 0), with Table 4.6's nominal step 0.5h²; right: θ = ¼.
load 'figures/style.gp'
set terminal svg size 960,440 dynamic enhanced font 'Helvetica,12' background rgb 'white'
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
set xtics ('2^{-5}' 2**-5, '2^{-6}' 2**-6, '2^{-7}' 2**-7, '2^{-8}' 2**-8, '2^{-9}' 2**-9)
set format y '%g'
set xlabel 'particle spacing Δx'
set ylabel 'time step / h^2'
# Coarse levels on the left; a margin of a quarter level on either side.
stats f using (column("dx")) nooutput
set xrange [STATS_max*1.2:STATS_min/1.2]
set key at graph 0.98, graph 0.89 right top box opaque font ',9' spacing 1.0 samplen 2.5
set multiplot
set bmargin at screen 0.13; set tmargin at screen 0.92
set lmargin at screen 0.08; set rmargin at screen 0.49
set title 'explicit (θ = 0)'
set yrange [0:0.55]   # room for the key between the limits and the 0.5 h² line
plot for [i=1:3] sel(i, 'printed') using (column("dx")):(column("limit_over_h2_0")) with linespoints lt i dt 1 title sprintf('%s: limit, printed h', wn(i)), \
     for [i=1:3] sel(i, 'scaled') using (column("dx")):(column("limit_over_h2_0")) with linespoints lt i dt 2 pt openpt(i) title sprintf('%s: limit, scaled h', wn(i)), \
     for [i=1:3] sel(i, 'printed') using (column("dx")):(column("bound_over_h2_0")) with linespoints lt i dt 3 lw 1 pt 1 title sprintf('%s: bound (3.3), δ = 1', wn(i)), \
     0.5 with lines lc rgb '#000000' dt 4 lw 1 title 'Table 4.6: 0.5 h^2'
set title 'θ = 1/4'
set lmargin at screen 0.58; set rmargin at screen 0.98
set yrange [0:0.55]
unset key
plot for [i=1:3] sel(i, 'printed') using (column("dx")):(column("limit_over_h2_q")) with linespoints lt i dt 1 notitle, \
     for [i=1:3] sel(i, 'scaled') using (column("dx")):(column("limit_over_h2_q")) with linespoints lt i dt 2 pt openpt(i) notitle, \
     for [i=1:3] sel(i, 'printed') using (column("dx")):(column("bound_over_h2_q")) with linespoints lt i dt 3 lw 1 pt 1 notitle
unset multiplot
