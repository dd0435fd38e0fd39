# Imoto Figures 1 and 4: the jittered particle distribution at dx = 2^-5 (N = 1,521) in
# Omega_H = (-0.1, 1.1)^2, with Omega = (0,1)^2 shaded.
load 'figures/style.gp'
set terminal svg size 560,560 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/imoto_figs_particles.tsv'
unset logscale xy
unset grid
set format x '%g'
set format y '%g'
set size ratio -1
set xrange [-0.1:1.1]
set yrange [-0.1:1.1]
set object 1 rectangle from 0,0 to 1,1 fc rgb '#d9d9d9' fs solid 1.0 noborder behind
set key outside below
plot rows_named(f, '$c["in_omega"]==1') using (column("x")):(column("y")) with points pt 7 ps 0.25 lc rgb '#000000' title 'particles in Ω (shaded)', \
     rows_named(f, '$c["in_omega"]==0') using (column("x")):(column("y")) with points pt 6 ps 0.25 lc rgb '#555555' title 'particles in Ω_H outside Ω'
