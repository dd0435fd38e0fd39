# Koba & Sato, Figure 2 (Voronoi diagram) around a_k: the cells sigma_i, the cell sigma_k
# (dark), the cells of R(a_k, h) (light), and the discs of radius delta, r_sigma, lambda*h
# and h around a_k, each with its radius drawn and labelled.
load 'figures/style.gp'
set output out
fp = datadir.'/koba_sato_fig_particles.tsv'
fcell = datadir.'/koba_sato_fig_cells.tsv'
fc = datadir.'/koba_sato_fig_circles.tsv'
val(name, col) = real(system(sprintf("awk -F'\t' '$1==\"%s\"{print $%d; exit}' '%s'", name, col, fc)))
ax = val('h', 2); ay = val('h', 3)
h = val('h', 4); rs = val('r_sigma', 4); d = val('delta', 4); lh = val('lambda_h', 4)
# The cells as polygons separated by blank lines (one vertex per row in the data file).
cells(cond) = sprintf("< awk -F'\t' '!/^#/ && $1!=\"cell\" && (%s) { if ($1!=prev) print \"\"; prev=$1; print $2\"\t\"$3 }' '%s'", cond, fcell)
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
plot cells('$4=="R"') using 1:2 with filledcurves closed fc rgb '#dde8f6' title 'σ_i, i ∈ R(a_k, h)', \
     cells('$4=="k"') using 1:2 with filledcurves closed fc rgb '#f4c7c3' title 'σ_k', \
     cells('1') using 1:2 with lines lc rgb '#888888' dt 1 lw 0.8 notitle, \
     rows(fp, '$4=="o" || $4=="R"') using 1:2 with points pt 7 ps 0.5 lc rgb '#1f4e9c' title 'a_i', \
     rows(fp, '$4=="k"') using 1:2 with points pt 7 ps 0.9 lc rgb '#b22222' title 'a_k', \
     rows(fc, '$1=="delta"') using 2:3:4 with circles fs empty lc rgb '#000000' dt 1 lw 1.5 title 'B_δ(a_k)', \
     rows(fc, '$1=="r_sigma"') using 2:3:4 with circles fs empty lc rgb '#2e7d32' dt 1 lw 1.5 title 'B_{r_σ}(a_k)', \
     rows(fc, '$1=="lambda_h"') using 2:3:4 with circles fs empty lc rgb '#6a1b9a' dt 2 lw 1.5 title 'B_{λh}(a_k)', \
     rows(fc, '$1=="h"') using 2:3:4 with circles fs empty lc rgb '#b22222' dt 1 lw 1.5 title 'B_h(a_k)'
