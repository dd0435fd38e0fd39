# Imoto Figure 3: covering radius of a uniform and a non-uniform distribution with the same N.
# Omega_H is the black square.  The disc is centred at the Voronoi vertex farthest from its particle; its radius is r_N.
load 'figures/style.gp'
set terminal svg size 1000,520 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
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
  c = sprintf('$c["distribution"]=="%s"', d)
  stats rows_named(df, c) using (column("r_N")) nooutput
  set title sprintf('%s: r_N = %.4f', d, STATS_max)
  plot rows_named(ef, c) using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lw 0.7 lc rgb '#1f4e9c' title 'Voronoi cells', \
       rows_named(pf, c) using (column("x")):(column("y")) with points pt 7 ps 0.5 lc rgb '#000000' title 'particles', \
       rows_named(df, c) using (column("centre_x")):(column("centre_y")):(column("r_N")) with circles lw 2 dt 1 lc rgb '#b22222' fs empty border lc rgb '#b22222' title 'covering disc (radius r_N)', \
       rows_named(df, c) using (column("worst_x")):(column("worst_y")) with points pt 5 ps 1.0 lc rgb '#b22222' title 'particle of the worst cell'
}
unset multiplot
