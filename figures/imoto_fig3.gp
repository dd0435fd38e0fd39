# Imoto Figure 3: covering radius of a uniform and a non-uniform distribution with the same N.
# Omega_H is the black square.  The disc is centred at the Voronoi vertex farthest from its particle; its radius is r_N.
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing
# prints below 8 pt; the two square panels side by side, placed by hand, and one key (the
# same four elements in both) in a strip below them.
load 'figures/style.gp'
W = 760; Hc = 476
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
pf = datadir.'/imoto_figs_fig3_particles.tsv'
ef = datadir.'/imoto_figs_fig3_edges.tsv'
df = datadir.'/imoto_figs_fig3_discs.tsv'
unset logscale xy
unset grid
set format x '%g'
set format y '%g'
set xrange [-0.15:1.4]
set yrange [-0.15:1.4]
set object 1 rectangle from -0.1,-0.1 to 1.1,1.1 fs empty border lc rgb '#000000' lw 1.5
unset key
# Square panels (equal x and y ranges on a box as high as it is wide, in px).
PL = 44.0 / W; PR = 1 - 12.0 / W; GX = 44.0 / W; PW = (PR - PL - GX) / 2
PT = 1 - 40.0 / Hc; PH = PW * W / Hc; GY = 0
set multiplot
i = 0
do for [d in "uniform non-uniform"] {
  i = i + 1
  c = sprintf('$c["distribution"]=="%s"', d)
  stats rows_named(df, c) using (column("r_N")) nooutput
  set title sprintf('%s: r_N = %.4f', d, STATS_max) offset 0,-0.4
  eval panel_at(i, 1)
  plot rows_named(ef, c) using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lw 0.7 lc rgb '#1f4e9c' notitle, \
       rows_named(pf, c) using (column("x")):(column("y")) with points pt 7 ps 0.5 lc rgb '#000000' notitle, \
       rows_named(df, c) using (column("centre_x")):(column("centre_y")):(column("r_N")) with circles lw 2 dt 1 lc rgb '#b22222' fs empty border lc rgb '#b22222' notitle, \
       rows_named(df, c) using (column("worst_x")):(column("worst_y")) with points pt 5 ps 1.0 lc rgb '#b22222' notitle
}
# The key: the four elements of both panels, in one strip under them.
KEY_TOP = 62.0 / Hc; eval key_strip
set key center center horizontal maxrows 2 samplen 2.5 width -2 box noopaque
set samples 2
plot '+' using (NaN):(NaN):(NaN):(NaN) with vectors nohead lw 0.7 lc rgb '#1f4e9c' title 'Voronoi cells', \
     NaN with points pt 7 ps 0.5 lc rgb '#000000' title 'particles', \
     '+' using (NaN):(NaN):(NaN) with circles lw 2 dt 1 lc rgb '#b22222' fs empty border lc rgb '#b22222' title 'covering disc (radius r_N)', \
     NaN with points pt 5 ps 1.0 lc rgb '#b22222' title 'particle of the worst cell'
unset multiplot
