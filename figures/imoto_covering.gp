# Covering radius r_N/dx of the Sec. 5 distribution for dx = 2^-5 .. 2^-10, against Imoto's
# claim r_N <= sqrt(2)(1+1/4)dx/2.  Left: five seeds; right: seed 1 over all cells and over the
# cells of particles in Ω only, with the bound sqrt(2)(1+1/2)/2 that holds for interior cells.
# The panels share their axes.
load 'figures/style.gp'
# Print size: 760 px wide (A4 text width 703 px), text 13-14 px, nothing below 8 pt.
set terminal svg size 760,540 dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/imoto_regularity_cover.tsv'
unset logscale y
set format y '%g'
set format x '2^{%L}'
set logscale x 2
# A margin of a quarter level on either side (points on the frame would be cut in half).
stats f using (column("dx")) name 'DX' nooutput
set xrange [DX_min/1.2:DX_max*1.2]
set xlabel 'Δx'
set ylabel 'r_N / Δx'
set yrange [0.8:1.45]
set key below center vertical maxrows 6 font ',14' samplen 2
seed(s) = rows_named(f, sprintf('$c["seed"]==%d', s))
set multiplot layout 1,2 margins 0.09,0.98,0.42,0.92 spacing 0.06,0
set title 'five seeds'
plot for [s=1:5] seed(s) using (column("dx")):(column("r_N_over_dx")) with linespoints lt s title sprintf('r_N, seed %d', s), \
     seed(1) using (column("dx")):(column("claim_over_dx")) with lines lt 7 title 'claim √2(1+1/4)/2 (Imoto §5)'
set title 'seed 1: all cells, cells in Ω'
set ylabel ''
plot seed(1) using (column("dx")):(column("r_N_over_dx")) with linespoints lt 1 title 'r_N, seed 1', \
     seed(1) using (column("dx")):(column("r_N_omega_over_dx")) with linespoints lt 6 title 'seed 1, cells of particles in Ω', \
     seed(1) using (column("dx")):(column("claim_over_dx")) with lines lt 7 title 'claim √2(1+1/4)/2 (Imoto §5)', \
     seed(1) using (column("dx")):(sqrt(2)*1.5/2) with lines lt 8 title 'interior bound √2(1+1/2)/2'
unset multiplot
