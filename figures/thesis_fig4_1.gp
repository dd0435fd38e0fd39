# Thesis Figure 4.1: the particle distribution at dx = 2^-5 (N = 1,521); grey area: Omega.
load 'figures/style.gp'
set terminal svg size 560,560 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set size ratio -1; set xrange [-0.1:1.1]; set yrange [-0.1:1.1]
set object 1 rect from 0,0 to 1,1 fc rgb '#d8d8d8' fs solid noborder behind
p = datadir.'/thesis_fig4_1_particles.tsv'
N = system(sprintf("awk -F' = ' '/^# N =/{print $2}' '%s'", p))
set title sprintf('Δx = 2^{-5}, N = %s', N)
plot p using (column("x")):(column("y")) with points lt 1 pt 7 ps 0.3 notitle
