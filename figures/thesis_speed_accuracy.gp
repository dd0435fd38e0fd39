# Speed versus accuracy (beyond the thesis): relative error (Case 2) against the wall time of
# a level, per weight and volume choice, scaled h reading where it exists (printed for Table
# 4.1, where both readings coincide).  Time = fused pass (all weights of the table at once)
# plus, for Voronoi volumes, the Voronoi computation.  Left: the interpolants (Tables 4.1 and
# 4.2); right: gradient and Laplacian (Table 4.3); both panels share their axes.
load 'figures/style.gp'
# Print size: 760 px wide (A4 text width 703 px), text 13-14 px, nothing below 8 pt.
set terminal svg size 760,680 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
set xlabel 'wall time [s] (pass + Voronoi)'
set format x '10^{%L}'
set key below center vertical maxrows 6 font ',14' samplen 2
sel(f, r, v, w, o) = rows_named(f, sprintf('$c["h_reading"]=="%s" && $c["volumes"]=="%s" && $c["weight"]=="%s" && $c["operator"]=="%s" && $c["function"]=="case2"', r, v, w, o))
f1 = datadir.'/thesis_table4_1.tsv'; f2 = datadir.'/thesis_table4_2.tsv'; f3 = datadir.'/thesis_table4_3.tsv'
T = '(column("time_s")+column("voronoi_s")):(column("rel_error"))'
# Shared decade-aligned ranges over every series drawn (before any range is set).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
all = sprintf("< awk -F'\t' 'FNR == 1 { hd = 0 } /^#/ { next } !hd++ { delete c; for (i=1;i<=NF;i++) c[$i]=i; if (!h++) print \"t\\te\"; next } $c[\"function\"]==\"case2\" && $c[\"rel_error\"] != \"NA\" { print $c[\"time_s\"] + $c[\"voronoi_s\"] \"\\t\" $c[\"rel_error\"] }' '%s' '%s' '%s'", f1, f2, f3)
stats all using (column("t")):(column("e")) nooutput
set xrange [lo(STATS_min_x):hi(STATS_max_x)]
set yrange [lo(STATS_min_y):hi(STATS_max_y)]
set multiplot layout 1,2 margins 0.11,0.98,0.4,0.93 spacing 0.07,0
set title 'Π (Tables 4.1, 4.2)'
set ylabel 'relative ℓ^∞(Ω) error, Case 2'
plot sel(f1, 'printed', 'voronoi', 'quadratic_spike', 'interp') using @T with linespoints lt 1 dt 1 title 'quadr. spike, Voronoi (T4.1)', \
     sel(f1, 'printed', 'uniform', 'quadratic_spike', 'interp') using @T with linespoints lt 1 dt 3 pt 6 title 'quadr. spike, |Ω_H|/N (T4.1)', \
     sel(f1, 'printed', 'voronoi', 'quintic_bspline', 'interp') using @T with linespoints lt 2 dt 1 title 'quintic-B, Voronoi (T4.1)', \
     sel(f1, 'printed', 'uniform', 'quintic_bspline', 'interp') using @T with linespoints lt 2 dt 3 pt 4 title 'quintic-B, |Ω_H|/N (T4.1)', \
     sel(f2, 'scaled', 'voronoi', 'cubic_spike', 'interp') using @T with linespoints lt 3 dt 1 title 'cubic spike, Voronoi (T4.2 scaled)', \
     sel(f2, 'scaled', 'uniform', 'cubic_spike', 'interp') using @T with linespoints lt 3 dt 3 pt 8 title 'cubic spike, |Ω_H|/N (T4.2 scaled)'
set title '∇ and Δ, quartic (Table 4.3)'
set ylabel ''
plot sel(f3, 'scaled', 'voronoi', 'quartic_polynomial', 'grad') using @T with linespoints lt 4 dt 1 title '∇, Voronoi', \
     sel(f3, 'scaled', 'uniform', 'quartic_polynomial', 'grad') using @T with linespoints lt 4 dt 3 pt 10 title '∇, |Ω_H|/N', \
     sel(f3, 'scaled', 'voronoi', 'quartic_polynomial', 'lap') using @T with linespoints lt 5 dt 1 title 'Δ, Voronoi', \
     sel(f3, 'scaled', 'uniform', 'quartic_polynomial', 'lap') using @T with linespoints lt 5 dt 3 pt 12 title 'Δ, |Ω_H|/N'
unset multiplot
