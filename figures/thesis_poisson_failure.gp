# Where the discrete Poisson problem fails (thesis_poisson_failure).
# Left: the h sweep on jittered grids (quartic polynomial): relative error of the solve with
#   the connectivity check switched off, against h/Δx, one line per seed over the connected
#   radii (incl. those just above each seed's threshold h*); the unconnected solves that end
#   in a NumericalError are crosses on the top edge, one that returned is a large circle at its
#   error, and the share of particles of Ω
#   that are cut off from Γ ∪ Γ_H (right axis) shows where h-connectivity is lost.
# Right: the maximum-principle probe (f = 0, data ≤ 0 outside Ω, so U ≤ 0 is promised):
#   max_Ω U / max_Ω |U| against Δx, for the cubic spike (negative on (4/7, 1)) and the
#   positive quartic polynomial, both readings of h.  Above 0 = the principle is violated.
load 'figures/style.gp'
# Print size: 760 px wide (A4 text width 703 px), text 13-14 px, nothing below 8 pt.
set terminal svg size 760,720 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
fa = datadir.'/thesis_poisson_failure.tsv'
fb = datadir.'/thesis_poisson_failure_h.tsv'
set multiplot layout 2,1  # one above the other: each panel the full width

# --- left panel: h sweep ---------------------------------------------------------------
set title 'h below the h-connectivity threshold (Δx = 2^{-5})'
unset logscale x
set xrange [0.45:2.05]
set yrange [1e-2:1e18]
set xlabel 'h / Δx'
set ylabel 'unchecked solve: max_Ω|ũ − U| / max_Ω|ũ|'
set y2label 'share of Ω cut off from Γ ∪ Γ_H'
set y2range [0:1.02]
set y2tics 0.25 nomirror
set ytics nomirror
set key at graph 0.98, graph 0.62 right top box opaque font ',14' samplen 1.5
set format y '10^{%L}'
set ytics 1e-2, 1e4
ok(s) = rows_named(fb, sprintf('$c["level"]=="5" && $c["seed"]=="%d" && $c["connected"]=="yes"', s))
plot ok(1) using (column("h_over_dx")):(column("rel_error")) smooth unique with linespoints lt 1 title 'seed 1', \
     ok(2) using (column("h_over_dx")):(column("rel_error")) smooth unique with linespoints lt 2 title 'seed 2', \
     ok(3) using (column("h_over_dx")):(column("rel_error")) smooth unique with linespoints lt 3 title 'seed 3', \
     ok(4) using (column("h_over_dx")):(column("rel_error")) smooth unique with linespoints lt 4 title 'seed 4', \
     rows_named(fb, '$c["level"]=="5" && $c["unchecked_status"]!="ok"') using (column("h_over_dx")):(1e17) with points lt 1 pt 2 ps 1.2 title 'unchecked CG throws', \
     rows_named(fb, '$c["level"]=="5" && $c["seed"]=="1"') using (column("h_over_dx")):(column("unconnected")/column("N_omega")) axes x1y2 smooth unique with lines lt 7 lw 1 title 'cut off, seed 1'

# --- right panel: maximum principle -------------------------------------------------------
set title 'maximum principle, data ≤ 0 outside Ω'
unset y2label
unset y2tics
set ytics mirror
set logscale x 2
set format x '2^{%L}'
unset logscale y
set format y '%g'
set ytics autofreq
set xrange [*:*] reverse
set autoscale x
set xrange [*:*] reverse
set yrange [-0.15:1.15]
set xlabel 'Δx'
set ylabel 'max_Ω U / max_Ω |U|   (> 0: violated)'
set key at graph 0.98, graph 0.6 right top box opaque font ',14' samplen 1.5
# A failed solve (no number) leaves fewer than three points: those series are drawn as points only.
cond(r, w) = sprintf('$c["h_rule"]=="%s" && $c["weight"]=="%s"', r, w)
sel(r, w) = rows_named(fa, cond(r, w))
line(r, w) = rows_trend(fa, cond(r, w), 'mp_boundary')
plot sel('h10', 'cubic_spike') using (column("dx")):(column("mp_boundary")) with points lt 3 title 'cubic spike, printed h', \
     line('h10', 'cubic_spike') using (column("dx")):(column("mp_boundary")) with lines lt 3 notitle, \
     sel('h15', 'cubic_spike') using (column("dx")):(column("mp_boundary")) with points lt 5 title 'cubic spike, 2^{-15} reading', \
     line('h15', 'cubic_spike') using (column("dx")):(column("mp_boundary")) with lines lt 5 notitle, \
     sel('h10', 'quartic_polynomial') using (column("dx")):(column("mp_boundary")) with points lt 1 title 'quartic, printed h', \
     line('h10', 'quartic_polynomial') using (column("dx")):(column("mp_boundary")) with lines lt 1 notitle, \
     sel('h15', 'quartic_polynomial') using (column("dx")):(column("mp_boundary")) with points lt 2 title 'quartic, 2^{-15} reading', \
     line('h15', 'quartic_polynomial') using (column("dx")):(column("mp_boundary")) with lines lt 2 notitle, \
     0 with lines lt 7 lw 1 notitle
unset multiplot
