# The heat problem under both readings of h (printed (2.6⁴·2^-10·Δx)^{1/4}, solid, and
# (2.6⁴·2^-15·Δx)^{1/4}, dashed), one panel per time-step setting of Tables 4.5–4.7, the
# piecewise cubic weight, θ = 1/2 and 1, against Δx (the two readings give different h).
# Rows that blew up (blew_up = yes) have no error and are left out.
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing
# prints below 8 pt; the three panels side by side, placed by hand, each on its own error
# axis (the settings differ by decades), and one key in a strip below them (the same four
# series in every panel).
load 'figures/style.gp'
W = 760; Hc = 500
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
set format x '2^{%L}'
set logscale x 2
unset key
w = 'piecewise_cubic_polynomial'
sel(f, t) = rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["blew_up"]=="no"', w, t))
PL = 78.0 / W; PR = 1 - 14.0 / W; GX = 56.0 / W; PW = (PR - PL - 2 * GX) / 3
PT = 1 - 68.0 / Hc; PB = 130.0 / Hc; GY = 0; PH = PT - PB
# The heat tables are the registry's (make passes heat_studies, STUDIES_heat of
# build/studies.mk); each panel's title is read from its data file's header.
if (!exists("heat_studies")) { print "thesis_heat_readings.gp: give heat_studies (make passes it)"; exit status 1 }
meta(f, key) = system(sprintf("sed -n 's/^# %s = //p' '%s' | head -1", key, f))
set multiplot
i = 0
do for [s in heat_studies] {
  i = i + 1
  f10 = datadir.'/'.s.'.tsv'
  f15 = datadir.'/'.s.'_h15.tsv'
  # A margin of a quarter level on either side (points on the frame would be cut in half).
  stats f10 using (column("dx")) name 'DX' nooutput
  set xrange [DX_min / 1.2 : DX_max * 1.2]
  set title sprintf("Table %s\nΔt = %s", meta(f10, 'table'), meta(f10, 'dt_nominal'))
  set ylabel (i == 1 ? 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))' : '')
  set xlabel 'Δx' offset 0,0.3
  eval panel_at(i, 1)
  plot sel(f10, '0.5') using (column("dx")):(column("rel_error")) with linespoints lt 1 notitle, \
       sel(f10, '1')   using (column("dx")):(column("rel_error")) with linespoints lt 3 notitle, \
       sel(f15, '0.5') using (column("dx")):(column("rel_error")) with linespoints lt 2 notitle, \
       sel(f15, '1')   using (column("dx")):(column("rel_error")) with linespoints lt 4 notitle
}
# The key: the four series of every panel, in one strip under the panels.
KEY_TOP = 66.0 / Hc; eval key_strip
set key center center horizontal maxrows 2 samplen 2.5 width -1 box noopaque
plot NaN with linespoints lt 1 title 'θ = 1/2, printed h', \
     NaN with linespoints lt 3 title 'θ = 1, printed h', \
     NaN with linespoints lt 2 title 'θ = 1/2, 2^{-15} reading', \
     NaN with linespoints lt 4 title 'θ = 1, 2^{-15} reading'
unset multiplot
