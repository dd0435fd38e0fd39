# imoto Figure 3: covering radius of a uniform and a non-uniform distribution with the same N.
# Omega_H is the black square.  The disc is centred at the Voronoi vertex farthest from its particle; its radius is r_N.
load 'figures/style.gp'
set terminal svg size 1000,520 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
pf = datadir.'/imoto_figs_fig3_particles.tsv'
ef = datadir.'/imoto_figs_fig3_edges.tsv'
df = datadir.'/imoto_figs_fig3_discs.tsv'
unset logscale xy
unset grid
set format x '%g'
set format y '%g'
set size ratio -1
set xrange [-0.15:1.4]
set yrange [-0.15:1.4]
set object 1 rectangle from -0.1,-0.1 to 1.1,1.1 fs empty border lc rgb '#000000' lw 1.5
set key outside below
set multiplot layout 1,2
do for [d in "uniform non-uniform"] {
  c = sprintf('$1=="%s"', d)
  stats rows(df, c) using 7 nooutput
  set title sprintf('%s: r_N = %.4f', d, STATS_max)
  plot rows(ef, c) using 3:4:($5-$3):($6-$4) with vectors nohead lw 0.7 lc rgb '#1f4e9c' title 'Voronoi cells', \
       rows(pf, c) using 2:3 with points pt 7 ps 0.5 lc rgb '#000000' title 'particles', \
       rows(df, c) using 5:6:7 with circles lw 2 dt 1 lc rgb '#b22222' fs empty border lc rgb '#b22222' title 'covering disc (radius r_N)', \
       rows(df, c) using 3:4 with points pt 5 ps 1.0 lc rgb '#b22222' title 'particle of the worst cell'
}
unset multiplot
