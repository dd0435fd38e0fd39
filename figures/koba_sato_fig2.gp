# Koba & Sato, Figure 2 (Voronoi diagram) around a_k: the cells sigma_i, the cell sigma_k
# (dark), the cells of R(a_k, h) (light), and the discs of radius delta, r_sigma, lambda*h
# and h around a_k, each with its radius drawn and labelled.
load 'figures/style.gp'
set output out
set datafile columnheaders
fp = datadir.'/koba_sato_fig_particles.tsv'
fcell = datadir.'/koba_sato_fig_cells.tsv'
fc = datadir.'/koba_sato_fig_circles.tsv'
val(name, col) = real(system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"name\"]==\"%s\" { print $c[\"%s\"]; exit }' '%s'", name, col, fc)))
ax = val('h', 'x'); ay = val('h', 'y')
h = val('h', 'r'); rs = val('r_sigma', 'r'); d = val('delta', 'r'); lh = val('lambda_h', 'r')
# The cells as polygons separated by blank lines (one vertex per row in the data file), header
# kept, the condition on named columns as in rows_named.
cells(cond) = sprintf("< awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; print; next } (%s) { if ($c[\"cell\"]!=prev) print \"\"; prev=$c[\"cell\"]; print }' '%s'", cond, fcell)
unset logscale
set format x '%g'
set format y '%g'
set size ratio -1
w = 1.3*h
set xrange [ax-w:ax+w]
set yrange [ay-w:ay+w]
set xlabel 'x_1'
set ylabel 'x_2'
set key outside right top box opaque
set style fill solid 1.0 noborder
# Radii at different angles so that the four labels do not overlap.
set arrow 1 from ax,ay to ax+d*cos(-0.5),ay+d*sin(-0.5) nohead lc rgb '#000000' lw 1.5 front
set arrow 2 from ax,ay to ax+rs*cos(2.3),ay+rs*sin(2.3) nohead lc rgb '#2e7d32' lw 1.5 front
set arrow 3 from ax,ay to ax+lh*cos(3.6),ay+lh*sin(3.6) nohead lc rgb '#6a1b9a' lw 1.5 front
set arrow 4 from ax,ay to ax+h*cos(0.8),ay+h*sin(0.8) nohead lc rgb '#b22222' lw 1.5 front
set label 1 'δ' at ax+1.6*d*cos(-0.5),ay+1.6*d*sin(-0.5) center front font ',13'
set label 2 'r_σ' at ax+1.25*rs*cos(2.3),ay+1.25*rs*sin(2.3) center front font ',13' tc rgb '#2e7d32'
set label 3 'λh' at ax+1.12*lh*cos(3.6),ay+1.12*lh*sin(3.6) center front font ',13' tc rgb '#6a1b9a'
set label 4 'h' at ax+1.06*h*cos(0.8),ay+1.06*h*sin(0.8) center front font ',13' tc rgb '#b22222'
plot cells('$c["role"]=="R"') using (column("x")):(column("y")) with filledcurves closed fc rgb '#dde8f6' title 'σ_i, i ∈ R(a_k, h)', \
     cells('$c["role"]=="k"') using (column("x")):(column("y")) with filledcurves closed fc rgb '#f4c7c3' title 'σ_k', \
     cells('1') using (column("x")):(column("y")) with lines lc rgb '#888888' dt 1 lw 0.8 notitle, \
     rows_named(fp, '$c["role"]=="o" || $c["role"]=="R"') using (column("x")):(column("y")) with points pt 7 ps 0.5 lc rgb '#1f4e9c' title 'a_i', \
     rows_named(fp, '$c["role"]=="k"') using (column("x")):(column("y")) with points pt 7 ps 0.9 lc rgb '#b22222' title 'a_k', \
     rows_named(fc, '$c["name"]=="delta"') using (column("x")):(column("y")):(column("r")) with circles fs empty lc rgb '#000000' dt 1 lw 1.5 title 'B_δ(a_k)', \
     rows_named(fc, '$c["name"]=="r_sigma"') using (column("x")):(column("y")):(column("r")) with circles fs empty lc rgb '#2e7d32' dt 1 lw 1.5 title 'B(a_k, r_σ)', \
     rows_named(fc, '$c["name"]=="lambda_h"') using (column("x")):(column("y")):(column("r")) with circles fs empty lc rgb '#6a1b9a' dt 2 lw 1.5 title 'B(a_k, λh)', \
     rows_named(fc, '$c["name"]=="h"') using (column("x")):(column("y")):(column("r")) with circles fs empty lc rgb '#b22222' dt 1 lw 1.5 title 'B_h(a_k)'
