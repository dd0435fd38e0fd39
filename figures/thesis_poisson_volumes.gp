# Table 4.4 at the thesis' levels (result store, thesis_poisson_diagnostic): the Poisson error
# against h for the printed h, seed 1, with the thesis' volumes V_i = |Omega_H|/N (A.10, solid)
# and with V_i = dx^2 (dashed).  The grid does not tile Omega_H, so (A.10) is off by a volume
# mismatch that changes sign between 2^-8 and 2^-9 and flattens the solid curves; with dx^2
# they fall as h^2.  The slope-2 triangle sits under the two finest points of the lowest curve.
# Drawn at print size: 640 px wide (the figure sits in a list, about 580 px wide on the A4
# page), 14 px text, so nothing prints below 8 pt; the key inside, above the curves.
load 'figures/style.gp'
set terminal svg size 640,520 dynamic enhanced font 'Helvetica,14' background rgb 'white'
TRI_FONT = ',14'
set output out
set datafile columnheaders
f = storedir.'/thesis_poisson_diagnostic.tsv'
set xlabel 'influence radius h (printed: (2.6^4 2^{-10} Δx)^{1/4})'
set ylabel 'max_Ω|u − U| / max_Ω|u|  (ℓ^∞(Ω), relative)'
# Anchor: the two finest points of the lowest series (pw. quintic, V_i = dx^2).
anchor = rows_named(f, '$c["h_rule"]=="h10" && $c["weight"]=="piecewise_quintic_polynomial" && $c["variant"]=="seed1_cell" && $c["level"]>=8')
stats anchor using (column("h")) name "H" nooutput
stats anchor using (column("rel_error")) name "E" nooutput
set key top left font ',14' samplen 2.5 spacing 1.1
# Room left of the data for the triangle's label.
set xrange [0.08:0.145]
set xtics (0.08, 0.09, 0.1, 0.11, 0.12, 0.13, 0.14) format '%.2f'
set yrange [0.006:0.1]
set ytics (0.006, 0.01, 0.02, 0.03, 0.05, 0.1) format "%g"
w(i) = word('quartic_polynomial piecewise_cubic_polynomial piecewise_quintic_polynomial', i)
wn(i) = word('quartic pw.cubic pw.quintic', i)
sel(i, v) = rows_named(f, sprintf('$c["h_rule"]=="h10" && $c["weight"]=="%s" && $c["variant"]=="%s"', w(i), v))
eval triangle(H_min, E_min * 0.72, H_max / H_min, 2, 'slope 2')
plot for [i=1:3] sel(i, 'seed1') using (column("h")):(column("rel_error")) with linespoints lt i dt 1 \
       title sprintf('%s, V_i = |Ω_H|/N', wn(i)), \
     for [i=1:3] sel(i, 'seed1_cell') using (column("h")):(column("rel_error")) with linespoints lt i dt 2 pt (i == 1 ? 6 : i == 2 ? 4 : 8) \
       title sprintf('%s, V_i = Δx^2', wn(i))
