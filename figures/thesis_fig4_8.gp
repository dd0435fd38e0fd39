# Figure 4.8 (thesis §4.2): relative ℓ∞ error of the discrete Poisson problem against h,
# for the printed h = (2.6⁴·2^-10·Δx)^{1/4} (solid) and the reading (2.6⁴·2^-15·Δx)^{1/4}.
load 'figures/style.gp'
set output out
f = datadir.'/thesis_table4_4.tsv'
set xlabel 'influence radius h'
set ylabel 'max_Ω|ũ − U| / max_Ω|ũ|'
set key bottom right
xlo = 0.025; xhi = 0.25; eval pow2_xtics
eval triangle(0.14, 2e-3, 1.3, 2, 'slope 2')
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
sel(r, w) = rows(f, sprintf('$1=="%s" && $2=="%s"', r, w))
plot sel('h10', w1) using 5:10 with linespoints lt 1 title 'quartic, printed h', \
     sel('h10', w2) using 5:10 with linespoints lt 2 title 'pw. cubic, printed h', \
     sel('h10', w3) using 5:10 with linespoints lt 3 title 'pw. quintic, printed h', \
     sel('h15', w1) using 5:10 with linespoints lt 4 title 'quartic, 2^{-15} reading', \
     sel('h15', w2) using 5:10 with linespoints lt 5 title 'pw. cubic, 2^{-15} reading', \
     sel('h15', w3) using 5:10 with linespoints lt 6 title 'pw. quintic, 2^{-15} reading'
