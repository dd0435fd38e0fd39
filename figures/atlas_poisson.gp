# Atlas of the discrete Poisson problem (thesis Table 4.4): relative error
# max_Ω|ũ − U| / max_Ω|ũ| (ℓ^∞(Ω)) against the wall time of assembly + CG solve (left) and the
# matrix nonzeros (right), per weight (point type) and h rule (dash pattern); the panels share
# the error axis, and one legend sits in a strip below them.  Columns are addressed by name
# (rel_error, time_s, pairs (= nonzeros), h_rule, weight of atlas_poisson.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing prints
# below 8 pt; panels placed by hand with panel_at.
load 'figures/style.gp'
W = 760; Hc = 470
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/atlas_poisson.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ws = uniq('weight'); hs = uniq('h_rule'); nh = words(hs)
J(i) = i / nh + 1; R(i) = i % nh + 1
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w
set format x '10^{%T}'
set format y '10^{%T}'
unset key
# One error range for both panels (decade-aligned; before any range is set).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
stats f using (column("rel_error")) name 'SY' nooutput
set yrange [lo(SY_min):hi(SY_max)]
set multiplot title 'Thesis Table 4.4 (Poisson): accuracy against cost' font ',15'
PL = 92.0 / W; PR = 1 - 20.0 / W; GX = 52.0 / W; PW = (PR - PL - GX) / 2
PT = 1 - 72.0 / Hc; PB = 150.0 / Hc; GY = 0; PH = PT - PB
do for [c=1:2] {
  eval panel_at(c, 1)
  set title sprintf('error against %s', c == 1 ? 'wall time' : 'matrix nonzeros')
  set xlabel (c == 1 ? 'assembly + solve [s]' : 'nonzeros of the matrix') offset 0,0.4
  set ylabel (c == 1 ? 'max_Ω|ũ − U| / max_Ω|ũ|' : '')
  set format y (c == 1 ? '10^{%T}' : '')
  plot for [i=0:words(ws)*nh-1] rows_named(f, sprintf('$c["weight"]=="%s" && $c["h_rule"]=="%s"', word(ws, J(i)), word(hs, R(i)))) \
       using (column(c == 1 ? "time_s" : "pairs")):(column("rel_error")) with linespoints lt J(i) dt R(i) notitle
}
# The key: under the panels, one column per weight (point type), one row per h rule (dash).
KEY_TOP = 80.0 / Hc; eval key_strip
set key center center vertical maxrows nh samplen 2.5 width -4 box noopaque noenhanced  # drawn once (an opaque key is drawn twice)
plot for [i=0:words(ws)*nh-1] NaN with linespoints lt J(i) dt R(i) \
     title sprintf('%s, h rule %s', sh(word(ws, J(i))), word(hs, R(i)))
unset multiplot
