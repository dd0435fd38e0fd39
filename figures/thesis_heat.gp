# Shared body of Figures 4.9–4.11: the relative error (4.2) of the discrete heat problem
# against h, one panel per θ in `thetas` (space-separated), one series per weight (the same
# line style for a weight in every panel), from data file `f` (rows that blew up have rel_error
# NA and are left out); `slopes` gives the theoretical rate per theta for the slope triangle of
# its panel; P is the published long-format table (weight, theta, numerical): each series gets a
# grey segment rising with the PUBLISHED rate over the documents' level pair (style.gp's
# published_segment; where the rate agrees, the segment lies on the data).  The panels share both axes.
# Drawn at print size: 760 px wide (the A4 text width is 703 px) with 14 px text, so nothing
# prints below 8 pt; one legend, below the panels.
load 'figures/style.gp'
nth = words(thetas)
W = 760
set terminal svg size W,360 dynamic enhanced font 'Helvetica,14' background rgb 'white'
TRI_FONT = ',14'
TRI_BELOW = 1  # the triangles sit at the panels' left edge (the finest h)

set output out
set datafile columnheaders
set xlabel 'influence radius h'
set ylabel 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))'
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
wl(i) = i == 1 ? w1 : i == 2 ? w2 : w3
wn(i) = i == 1 ? 'quartic' : i == 2 ? 'pw. cubic' : 'pw. quintic'
th(j) = word(thetas, j)
thn(t) = t eq '0.5' ? '1/2' : t
sel(i, j) = rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["blew_up"]=="no"', wl(i), th(j)))
pub(w, t) = published_rate(P, sprintf('$c["weight"]=="%s" && $c["theta"]+0==%s', w, t))
# Both axes from all the data, before any range is set (stats applies the current ranges).
stats f using (column("h")) name 'EX' nooutput
# Room below the data for the triangles (which sit under the finest points); only the θ drawn
# (an explicit run that did not blow up under Δt = 0.5h² would stretch the axis by decades).
stats rows_named(f, sprintf('$c["blew_up"]=="no" && index(" %s ", " " $c["theta"] " ")', thetas)) using (column("rel_error")) name 'EY' nooutput
# Equal panels placed by hand, then the key alone in a strip below them (never over the data
# or the triangles; a key inside a narrow panel would stack its entries).
set multiplot
PL = 95.0 / W; PR = 1 - 28.0 / W; GX = 12.0 / W; PW = (PR - PL - (nth - 1) * GX) / nth
PT = 0.9; PH = 0.9 - 0.25; GY = 0
unset key
do for [j=1:nth] {
  eval panel_at(j, 1)
  unset object; unset arrow; unset label
  set autoscale xy; set logscale x 10  # drop the previous panel's ranges before the stats below
  set title sprintf('θ = %s', thn(th(j)))
  # The slope triangle under the two finest points of this θ's quartic series.
  ANCHOR = sel(1, j); eval anchored_triangle(word(slopes, j) + 0, 'slope '.word(slopes, j))
  do for [i=1:3] {
    ANCHOR = sel(i, j)
    p = pub(wl(i), th(j))
    # A rate far from any data (Table 4.6's -281 for the explicit step) is not drawn.
    if (p == p && abs(p) < 20) { eval published_segment(p) }
  }
  xlo = EX_min * 0.72; xhi = EX_max * 1.15; eval pow2_xtics
  set yrange [EY_min / 5 : EY_max * 3]
  if (j > 1) { set ylabel ' '; set format y '' } else { set ylabel 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))'; set format y '10^{%L}' }
  plot for [i=1:3] sel(i, j) using (column("h")):(column("rel_error")) with linespoints lt i notitle
}
# The key: the same line types, in one row under the panels.
KEY_TOP = 0.09; eval key_strip
set key center center horizontal maxrows 1 samplen 1.5 width -3 box noopaque  # drawn once (an opaque key is drawn twice)
plot for [i=1:3] NaN with linespoints lt i title wn(i), NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'
unset multiplot
