# Covering radius r_c / dx against dx: plain grid (exact value known) and jittered grids
# (three seeds), with imoto's claimed bound sqrt(2)(1+1/4)/2 and the thesis' range [1.4, 1.8].
load 'figures/style.gp'
set output out
set datafile columnheaders
f = datadir.'/core_voronoi.tsv'
unset logscale y
set format y '%g'
set format x '2^{%L}'
set logscale x 2
set xlabel 'Δx'
set ylabel 'r_c / Δx'
set yrange [0.5:2.0]
set key outside below maxrows 4
plot rows_named(f, '$c["distribution"]=="grid" && $c["seed"]==1') using (column("dx")):(column("r_c_over_dx")) with linespoints lt 1 title 'plain grid (measured)', \
     rows_named(f, '$c["distribution"]=="grid" && $c["seed"]==1') using (column("dx")):(column("r_c_grid_pred")/column("dx")) with lines lt 7 title 'plain grid: √2·max(Δx/2, g)/Δx', \
     rows_named(f, '$c["distribution"]=="jittered" && $c["seed"]==1') using (column("dx")):(column("r_c_over_dx")) with linespoints lt 2 title 'jittered, seed 1', \
     rows_named(f, '$c["distribution"]=="jittered" && $c["seed"]==2') using (column("dx")):(column("r_c_over_dx")) with linespoints lt 3 title 'jittered, seed 2', \
     rows_named(f, '$c["distribution"]=="jittered" && $c["seed"]==3') using (column("dx")):(column("r_c_over_dx")) with linespoints lt 4 title 'jittered, seed 3', \
     rows_named(f, '$c["distribution"]=="jittered" && $c["seed"]==1') using (column("dx")):(column("r_c_omega_over_dx")) with linespoints lt 5 title 'jittered seed 1, cells of particles in Ω', \
     rows_named(f, '$c["distribution"]=="grid" && $c["seed"]==1') using (column("dx")):(column("imoto_bound")/column("dx")) with lines lt 6 title 'imoto §5 claim √2(1+1/4)/2', \
     1.4 with lines lt 8 title 'thesis Ch. 4 range 1.4–1.8', 1.8 with lines lt 8 notitle
