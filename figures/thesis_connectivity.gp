# Shared body of Figures 1.3-1.4: the graph G of Definition 1.8 for case C ('connected' or
# 'isolated'): edges |x_i - x_j| < h, particles outside Omega (the BFS sources) as open
# squares, particles in Omega as dots, unconnected particles and their edges marked.
load 'figures/style.gp'
set terminal svg size 600,640 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
unset logscale; set format x '%g'; set format y '%g'
set size ratio -1; set xrange [-0.1:1.1]; set yrange [-0.1:1.1]
set object 1 rect from 0,0 to 1,1 fc rgb '#eeeeee' fs solid noborder behind
set key outside below maxrows 2
p = datadir.'/thesis_connectivity_particles.tsv'; e = datadir.'/thesis_connectivity_edges.tsv'
H = system(sprintf("awk -F' = ' '/^# h =/{print $2}' '%s'", p))
OK = system(sprintf("awk -F' = ' '/^# h_connected_%s =/{print $2}' '%s'", C, p))
set title sprintf('%s, h = %.4g: h-connectivity %s', T, H+0, OK eq 'yes' ? 'holds' : 'fails')
# The connected case has no unconnected group: plot only the series that have points
# (an empty series makes gnuplot warn).
if (OK eq 'yes') {
plot rows_named(e, sprintf('$c["case"]=="%s" && $c["unconnected"]==0', C)) using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lt 7 dt 1 lw 0.4 title 'edges of G', \
     rows_named(p, sprintf('$c["case"]=="%s" && $c["in_omega"]==0', C)) using (column("x")):(column("y")) with points lt 2 pt 4 ps 0.5 title 'particles on Γ ∪ Γ_H (BFS sources)', \
     rows_named(p, sprintf('$c["case"]=="%s" && $c["in_omega"]==1 && $c["unconnected"]==0', C)) using (column("x")):(column("y")) with points lt 1 pt 7 ps 0.4 title 'particles in Ω reached'
} else {
plot rows_named(e, sprintf('$c["case"]=="%s" && $c["unconnected"]==0', C)) using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lt 7 dt 1 lw 0.4 title 'edges of G', \
     rows_named(e, sprintf('$c["case"]=="%s" && $c["unconnected"]==1', C)) using (column("x1")):(column("y1")):(column("x2")-column("x1")):(column("y2")-column("y1")) with vectors nohead lt 3 dt 1 lw 1.5 title 'edges of the unconnected group', \
     rows_named(p, sprintf('$c["case"]=="%s" && $c["in_omega"]==0', C)) using (column("x")):(column("y")) with points lt 2 pt 4 ps 0.5 title 'particles on Γ ∪ Γ_H (BFS sources)', \
     rows_named(p, sprintf('$c["case"]=="%s" && $c["in_omega"]==1 && $c["unconnected"]==0', C)) using (column("x")):(column("y")) with points lt 1 pt 7 ps 0.4 title 'particles in Ω reached', \
     rows_named(p, sprintf('$c["case"]=="%s" && $c["unconnected"]==1', C)) using (column("x")):(column("y")) with points lt 3 pt 9 ps 1.0 title 'particles in Ω not reached'
}
