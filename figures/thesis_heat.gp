# Shared body of Figures 4.9–4.11: the relative error (4.2) of the discrete heat problem
# against h for each weight and each θ in `thetas` (space-separated), from data file `f`
# (rows that blew up have rel_error NA and are left out).
load 'figures/style.gp'
set output out
set xlabel 'influence radius h'
set ylabel 'relative error (4.2)'
set key top left
xlo = 0.09; xhi = 0.22; eval pow2_xtics
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
wl(i) = i == 1 ? w1 : i == 2 ? w2 : w3
wn(i) = i == 1 ? 'quartic' : i == 2 ? 'pw. cubic' : 'pw. quintic'
th(j) = word(thetas, j)
sel(i, j) = rows(f, sprintf('$1=="%s" && $2=="%s" && $14=="no"', wl(i), th(j)))
thn(t) = t eq '0.5' ? '1/2' : t
plot for [j=1:words(thetas)] for [i=1:3] sel(i, j) using 5:11 with linespoints \
     lt (j-1)*3+i title sprintf('%s, θ = %s', wn(i), thn(th(j)))
