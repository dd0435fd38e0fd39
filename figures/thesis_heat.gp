# Shared body of Figures 4.9–4.11: the relative error (4.2) of the discrete heat problem
# against h for each weight and each θ in `thetas` (space-separated), from data file `f`
# (rows that blew up have rel_error NA and are left out); `slopes` gives the theoretical rate
# per theta for the slope triangles.
load 'figures/style.gp'
set terminal svg size 860,480 dynamic enhanced font 'Helvetica,12' background rgb 'white'  # room for the key outside
set output out
set datafile columnheaders
set xlabel 'influence radius h'
set ylabel 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))'
set key outside right top  # never over the data or the triangles
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
wl(i) = i == 1 ? w1 : i == 2 ? w2 : w3
wn(i) = i == 1 ? 'quartic' : i == 2 ? 'pw. cubic' : 'pw. quintic'
th(j) = word(thetas, j)
sel(i, j) = rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["blew_up"]=="no"', wl(i), th(j)))
# Slope triangles (`slopes`: one per theta, space-separated) under the two finest points of
# the quartic series of each theta.
do for [j=1:words(thetas)] { ANCHOR = sel(1, j); eval anchored_triangle(word(slopes, j) + 0, 'slope '.word(slopes, j)) }
thn(t) = t eq '0.5' ? '1/2' : t
xlo = 0.09; xhi = 0.22; eval pow2_xtics
plot for [j=1:words(thetas)] for [i=1:3] sel(i, j) using (column("h")):(column("rel_error")) with linespoints \
     lt (j-1)*3+i title sprintf('%s, θ = %s', wn(i), thn(th(j)))
