# Thesis Figure 4.2: graphs of the cubic B-spline, quintic B-spline and quadratic spike
# (the B-splines as corrected in the weight registry; see the errata).
load 'figures/style.gp'
set output out
unset logscale; set format x '%g'; set format y '%g'
set xlabel 'r'; set ylabel 'w(r)'; set xrange [0:1.2]
set key top right
f = datadir.'/thesis_fig_weights.tsv'
plot f using 1:3 with lines lt 1 title 'cubic B-spline', \
     f using 1:4 with lines lt 2 title 'quintic B-spline', \
     f using 1:2 with lines lt 3 title 'quadratic spike'
