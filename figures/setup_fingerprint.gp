# The set-up fingerprint (paper/04-setup-rule.md): for every stored reading of Table 4.6, how far
# its theta = 0 rates (explicit Euler, unstable) lie from the published -281, -314, -416: the
# distance mean |ln(rate/published)| over the three weights, seed 1 as a point, the stored
# jitter realizations' lowest and highest as a bar.  Read from gpm store-rates --ident
# (DATADIR/setup_identification.tsv).  A logarithmic axis, since the two h rules lie two orders
# of magnitude apart while volumes and time step move the distance by a factor of about two to
# four: the reader sees which details the fingerprint separates and which bars overlap.
load 'figures/style.gp'
set terminal svg size 640,400 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/setup_identification.tsv'
ident = system(sprintf("awk -F' = ' '/^# identified = / { print $2; exit }' '%s'", f))
unset logscale
set logscale x
set ytics noenhanced
set format x '10^{%L}'
set xlabel 'distance to the published θ = 0 rates, mean |ln(rate/published)|'
set ylabel ''
set grid xtics lc rgb '#dddddd'
set offsets graph 0.02, graph 0.05, graph 0.06, graph 0.06
set yrange [*:*] reverse
# The key above the plot, clear of every point.
set key outside top center horizontal noenhanced
set lmargin 14
plot f using (column("distance")):0:(column("distance_lo")):(column("distance_hi")):ytic(strcol("reading")) \
       with xerrorbars pt 7 ps 1.1 lc rgb '#1f5f9f' title 'seed 1 (bar: stored realizations)', \
     f using (strcol("reading") eq ident ? column("distance") : NaN):0 \
       with points pt 6 ps 2.4 lw 2 lc rgb '#b00000' title 'identified: '.ident
