# Speed versus accuracy (beyond the thesis): relative error (Case 2) against the wall time of
# a level, per weight and volume choice, scaled h reading where it exists (printed for Table
# 4.1, where both readings coincide).  Time = fused pass (all weights of the table at once)
# plus, for Voronoi volumes, the Voronoi computation.
load 'figures/style.gp'
set terminal svg size 1100,520 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
set xlabel 'wall time of the level [s] (pass + Voronoi)'
set ylabel 'relative ℓ^∞(Ω) error, Case 2'
set format x '10^{%L}'
set key outside right font ',9' samplen 2
sel(f, r, v, w, o) = rows_named(f, sprintf('$c["h_reading"]=="%s" && $c["volumes"]=="%s" && $c["weight"]=="%s" && $c["operator"]=="%s" && $c["function"]=="case2"', r, v, w, o))
f1 = datadir.'/thesis_table4_1.tsv'; f2 = datadir.'/thesis_table4_2.tsv'; f3 = datadir.'/thesis_table4_3.tsv'
plot sel(f1, 'printed', 'voronoi', 'quadratic_spike', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 1 dt 1 title 'Π quadr.spike, Voronoi (T4.1)', \
     sel(f1, 'printed', 'uniform', 'quadratic_spike', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 1 dt 3 pt 6 title 'Π quadr.spike, |Ω_H|/N (T4.1)', \
     sel(f1, 'printed', 'voronoi', 'quintic_bspline', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 2 dt 1 title 'Π quintic-B, Voronoi (T4.1)', \
     sel(f1, 'printed', 'uniform', 'quintic_bspline', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 2 dt 3 pt 4 title 'Π quintic-B, |Ω_H|/N (T4.1)', \
     sel(f2, 'scaled', 'voronoi', 'cubic_spike', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 3 dt 1 title 'Π cubic spike, Voronoi (T4.2 scaled)', \
     sel(f2, 'scaled', 'uniform', 'cubic_spike', 'interp') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 3 dt 3 pt 8 title 'Π cubic spike, |Ω_H|/N (T4.2 scaled)', \
     sel(f3, 'scaled', 'voronoi', 'quartic_polynomial', 'grad') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 4 dt 1 title '∇ quartic, Voronoi (T4.3 scaled)', \
     sel(f3, 'scaled', 'uniform', 'quartic_polynomial', 'grad') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 4 dt 3 pt 10 title '∇ quartic, |Ω_H|/N (T4.3 scaled)', \
     sel(f3, 'scaled', 'voronoi', 'quartic_polynomial', 'lap') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 5 dt 1 title 'Δ quartic, Voronoi (T4.3 scaled)', \
     sel(f3, 'scaled', 'uniform', 'quartic_polynomial', 'lap') using (column("time_s")+column("voronoi_s")):(column("rel_error")) with linespoints lt 5 dt 3 pt 12 title 'Δ quartic, |Ω_H|/N (T4.3 scaled)'
