# Thesis Figure 1.1: an example of a particle distribution X_{N,H} (jittered grid, dx = 2^-3).
load 'figures/style.gp'
set terminal svg size 520,520 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set size ratio -1; set xrange [-0.1:1.1]; set yrange [-0.1:1.1]
set object 1 rect from 0,0 to 1,1 fc rgb '#e8e8e8' fs solid border lc rgb '#000000' behind
set key outside below
p = datadir.'/thesis_fig1_1_particles.tsv'
plot p using (column("x")):(column("y")) with points lt 1 pt 7 ps 0.8 title 'particles x_i (grey: Ω, frame: Ω_H)'
