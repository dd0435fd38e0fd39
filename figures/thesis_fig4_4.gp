# Thesis Figure 4.4: graphs of the quadratic spike and the cubic spike (negative near r = 1).
load 'figures/style.gp'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set xlabel 'r'; set ylabel 'w(r)'; set xrange [0:1.2]
set key top right
set xzeroaxis lt 7
f = datadir.'/thesis_fig_weights.tsv'
plot f using (column("r")):(column("quadratic_spike")) with lines lt 1 title 'quadratic spike', \
     f using (column("r")):(column("cubic_spike")) with lines lt 2 title 'cubic spike'
