# The heat problem under both readings of h (printed (2.6⁴·2^-10·Δx)^{1/4}, solid, and
# (2.6⁴·2^-15·Δx)^{1/4}, dashed), one panel per time-step setting of Tables 4.5–4.7, the
# piecewise cubic weight, θ = 1/2 and 1, against Δx (the two readings give different h).
# Rows that blew up (blew_up = yes) have no error and are left out.
load 'figures/style.gp'
set terminal svg size 1080,400 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
set multiplot layout 1,3
set xlabel 'Δx'
set ylabel 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))'
set format x '2^{%L}'
set logscale x 2
set key bottom right font ',9'
w = 'piecewise_cubic_polynomial'
sel(f, t) = rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["blew_up"]=="no"', w, t))
do for [tab in '4_5 4_6 4_7'] {
  f10 = datadir.'/thesis_table'.tab.'.tsv'
  f15 = datadir.'/thesis_table'.tab.'_h15.tsv'
  set title tab eq '4_5' ? 'Table 4.5: Δt = 0.0025h²' : tab eq '4_6' ? 'Table 4.6: Δt = 0.5h²' : 'Table 4.7: Δt = 0.5h'
  plot sel(f10, '0.5') using (column("dx")):(column("rel_error")) with linespoints lt 1 title 'θ = 1/2, printed h', \
       sel(f10, '1')   using (column("dx")):(column("rel_error")) with linespoints lt 3 title 'θ = 1, printed h', \
       sel(f15, '0.5') using (column("dx")):(column("rel_error")) with linespoints lt 2 title 'θ = 1/2, 2^{-15} reading', \
       sel(f15, '1')   using (column("dx")):(column("rel_error")) with linespoints lt 4 title 'θ = 1, 2^{-15} reading'
}
unset multiplot
