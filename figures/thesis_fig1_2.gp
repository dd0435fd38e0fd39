# Thesis Figure 1.2: the Voronoi decomposition of Omega_H for the distribution of Figure 1.1.
load 'figures/style.gp'
set terminal svg size 520,520 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set size ratio -1; set xrange [-0.1:1.1]; set yrange [-0.1:1.1]
set object 1 rect from 0,0 to 1,1 fc rgb '#e8e8e8' fs solid noborder behind
set key outside below
p = datadir.'/thesis_fig1_1_particles.tsv'; c = datadir.'/thesis_fig1_2_cells.tsv'
plot c using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lt 2 dt 1 title 'Voronoi cells σ_i (clipped to Ω_H)', \
     p using (column("x")):(column("y")) with points lt 1 pt 7 ps 0.7 title 'particles'
