# Covering radius r_N/dx of the Sec. 5 distribution for dx = 2^-5 .. 2^-10 and five seeds,
# against imoto's claim r_N <= sqrt(2)(1+1/4)dx/2.
load 'figures/style.gp'
set output out
set datafile columnheaders
f = datadir.'/imoto_regularity_cover.tsv'
unset logscale y
set format y '%g'
set format x '2^{%L}'
set logscale x 2
set xlabel 'Δx'
set ylabel 'r_N / Δx'
set yrange [0.8:1.45]
set key outside below maxrows 4
plot for [s=1:5] rows_named(f, sprintf('$c["seed"]==%d', s)) using (column("dx")):(column("r_N_over_dx")) with linespoints lt s title sprintf('r_N, seed %d', s), \
     rows_named(f, '$c["seed"]==1') using (column("dx")):(column("r_N_omega_over_dx")) with linespoints lt 6 title 'seed 1, cells of particles in Ω', \
     rows_named(f, '$c["seed"]==1') using (column("dx")):(column("claim_over_dx")) with lines lt 7 title 'claim √2(1+1/4)/2 (imoto §5)', \
     rows_named(f, '$c["seed"]==1') using (column("dx")):(sqrt(2)*1.5/2) with lines lt 8 title 'interior bound √2(1+1/2)/2'
