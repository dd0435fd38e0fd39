# Thesis Figure 4.2: graphs of the cubic B-spline, quintic B-spline and quadratic spike
# (the B-splines as corrected in the weight registry; see the errata).
load 'figures/style.gp'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set xlabel 'r'; set ylabel 'w(r)'; set xrange [0:1.2]
set key top right
f = datadir.'/thesis_fig_weights.tsv'
plot f using (column("r")):(column("cubic_bspline")) with lines lt 1 title 'cubic B-spline', \
     f using (column("r")):(column("quintic_bspline")) with lines lt 2 title 'quintic B-spline', \
     f using (column("r")):(column("quadratic_spike")) with lines lt 3 title 'quadratic spike'
