# Shared body of Figures 4.9–4.11: the relative error (4.2) of the discrete heat problem
# against h for each weight and each θ in `thetas` (space-separated), from data file `f`
# (rows that blew up have rel_error NA and are left out); `slopes` gives the theoretical rate
# per theta for the slope triangles; P is the published long-format table (weight, theta,
# numerical): each series gets a grey segment from its finest point, rising with the
# PUBLISHED rate over the last interval (where the rate agrees, the segment lies on the data).
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
pub(w, t) = published_rate(P, sprintf('$c["weight"]=="%s" && $c["theta"]+0==%s', w, t))
do for [j=1:words(thetas)] {
  do for [i=1:3] {
    ANCHOR = sel(i, j)
    p = pub(wl(i), th(j))
    # A rate far from any data (Table 4.6's -281 for the explicit step) is not drawn.
    if (p == p && abs(p) < 20) { eval published_segment(p) }
  }
}
thn(t) = t eq '0.5' ? '1/2' : t
stats f using (column("h")) nooutput
xlo = STATS_min * 0.85; xhi = STATS_max * 1.15; eval pow2_xtics
# Room below the data for the triangles (which sit under the finest points).
stats rows_named(f, '$c["blew_up"]=="no"') using (column("rel_error")) name 'EY' nooutput
set yrange [EY_min / 5 : EY_max * 3]
plot for [j=1:words(thetas)] for [i=1:3] sel(i, j) using (column("h")):(column("rel_error")) with linespoints \
     lt (j-1)*3+i title sprintf('%s, θ = %s', wn(i), thn(th(j))), \
     NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'
