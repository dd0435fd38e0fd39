# Covering radius r_c / dx against dx.  Left: plain grid (exact value known); right: jittered
# grids (three seeds, and the cells of particles in Ω for seed 1).  Both panels carry Imoto's
# claimed bound sqrt(2)(1+1/4)/2 and the thesis' range [1.4, 1.8], and share their axes.
load 'figures/style.gp'
set terminal svg size 1000,500 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/core_voronoi.tsv'
unset logscale y
set format y '%g'
set format x '2^{%L}'
set logscale x 2
# A margin of a quarter level on either side (points on the frame would be cut in half).
stats f using (column("dx")) name 'DX' nooutput
set xrange [DX_min/1.2:DX_max*1.2]
set xlabel 'Δx'
set ylabel 'r_c / Δx'
set yrange [0.5:2.0]
set key below center vertical maxrows 6 font ',10' samplen 3
grid1 = rows_named(f, '$c["distribution"]=="grid" && $c["seed"]==1')
jit(s) = rows_named(f, sprintf('$c["distribution"]=="jittered" && $c["seed"]==%d', s))
set multiplot layout 1,2 margins 0.07,0.98,0.34,0.92 spacing 0.07,0
set title 'plain grid'
plot grid1 using (column("dx")):(column("r_c_over_dx")) with linespoints lt 1 title 'measured', \
     grid1 using (column("dx")):(column("r_c_grid_pred")/column("dx")) with lines lt 7 title 'exact: √2·max(Δx/2, g)/Δx', \
     grid1 using (column("dx")):(column("imoto_bound")/column("dx")) with lines lt 6 title 'Imoto §5 claim √2(1+1/4)/2', \
     1.4 with lines lt 8 title 'thesis Ch. 4 range 1.4–1.8', 1.8 with lines lt 8 notitle
set title 'jittered grid'
set ylabel ''
plot for [s=1:3] jit(s) using (column("dx")):(column("r_c_over_dx")) with linespoints lt s + 1 title sprintf('seed %d', s), \
     jit(1) using (column("dx")):(column("r_c_omega_over_dx")) with linespoints lt 5 title 'seed 1, cells of particles in Ω', \
     grid1 using (column("dx")):(column("imoto_bound")/column("dx")) with lines lt 6 title 'Imoto §5 claim √2(1+1/4)/2', \
     1.4 with lines lt 8 title 'thesis Ch. 4 range 1.4–1.8', 1.8 with lines lt 8 notitle
unset multiplot
