# Imoto Figure 2: the Voronoi decomposition of Omega_H for the distribution of Figure 4.
load 'figures/style.gp'
set terminal svg size 560,560 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
p = datadir.'/imoto_figs_particles.tsv'
v = datadir.'/imoto_figs_voronoi.tsv'
unset logscale xy
unset grid
set format x '%g'
set format y '%g'
set size ratio -1
set xrange [-0.1:1.1]
set yrange [-0.1:1.1]
set object 1 rectangle from 0,0 to 1,1 fc rgb '#eeeeee' fs solid 1.0 noborder behind
set key outside below
plot rows_named(v, '1') using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lw 0.5 lc rgb '#1f4e9c' title 'Voronoi cells σ_i', \
     rows_named(p, '1') using (column("x")):(column("y")) with points pt 7 ps 0.2 lc rgb '#000000' title 'particles x_i'
