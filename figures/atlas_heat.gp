# Atlas of the heat equation (thesis Tables 4.5-4.7): relative error (4.2), in
# ℓ^∞(0,T; ℓ^2(Ω_H)), against the wall time of all K steps of a run, one row per weight (named
# on the error axis) and one column per Δt rule (headed over the top row; 4.5: 0.0025 h²,
# 4.6: 0.5 h², 4.7: 0.5 h); in each panel one series per θ (line style = θ, the same in every
# panel, one legend in a strip below the panels).  The panels of a column share both axes (time
# tick labels under the bottom row only), so the weights compare down a column.  The heat runs
# record no pair count, so there is no pairs panel.  Series that blew up are not in the atlas.
# Columns are addressed by name (rel_error, time_s, weight, theta, dt_nominal of atlas_heat.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing prints
# below 8 pt; panels placed by hand with panel_at.
load 'figures/style.gp'
f = datadir.'/atlas_heat.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ws = uniq('weight'); ths = uniq('theta'); dts = uniq('dt_nominal')
nw = words(ws); nd = words(dts)
pos(list, x) = sum [k=1:words(list)] (word(list, k) eq x ? k : 0)
tidx(t) = pos(ths, t)  # the same θ keeps its style in every panel
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w
thn(t) = t eq '0.5' ? '1/2' : t
# A Δt rule as written in the data ('0.0025h^2') for enhanced text: 'Δt = 0.0025 h^2'.
dtn(d) = strstrt(d, 'h') > 0 ? sprintf('Δt = %s %s', d[1:strstrt(d, 'h') - 1], d[strstrt(d, 'h'):]) : 'Δt = '.d
W = 760; Hc = 80 + 205 * nw + 30 * (nw - 1) + 100
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
set format y '10^{%T}'
unset key
# Decade-aligned range of column c over the rows of the Δt rule d (before any range is set).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
set multiplot title 'Thesis Tables 4.5-4.7 (heat): error (4.2) in ℓ^∞(0,T; ℓ^2(Ω_H)) against cost' font ',15'
PL = 92.0 / W; PR = 1 - 20.0 / W; GX = 56.0 / W; PW = (PR - PL - (nd - 1) * GX) / nd
PT = 1 - 80.0 / Hc; GY = 30.0 / Hc; PH = 205.0 / Hc
do for [r=1:nw] {
  do for [d=1:nd] {
    set autoscale xy
    dsel = rows_named(f, sprintf('$c["dt_nominal"]=="%s"', word(dts, d)))
    stats dsel using (column("time_s")) name 'SX' nooutput
    stats dsel using (column("rel_error")) name 'SY' nooutput
    set xrange [lo(SX_min):hi(SX_max)]
    set yrange [lo(SY_min):hi(SY_max)]
    # A y axis over more than 6 decades gets a tick every second decade.
    if (log10(hi(SY_max) / lo(SY_min)) > 6) { set ytics 100 } else { set ytics autofreq }
    eval panel_at(d, r)
    if (r == 1) { set title dtn(word(dts, d)) } else { unset title }
    set format x (r == nw ? '10^{%T}' : '')
    set xlabel (r == nw ? 'wall time of the run [s]' : '') offset 0,0.4
    set ylabel (d == 1 ? sprintf("%s\nrelative error", sh(word(ws, r))) : '')
    # The θ present for this weight under this Δt rule (θ = 0 is absent where it blew up).
    cs = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"dt_nominal\"]==\"%s\" && $c[\"weight\"]==\"%s\" { print $c[\"theta\"] }' '%s' | sort -u | tr '\n' ' '", word(dts, d), word(ws, r), f))
    plot for [i=1:words(cs)] \
         rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["dt_nominal"]=="%s"', word(ws, r), word(cs, i), word(dts, d))) \
         using (column("time_s")):(column("rel_error")) with linespoints lt tidx(word(cs, i)) notitle
  }
}
# The key: one row under the panels (line style = θ, as in every panel).
KEY_TOP = 42.0 / Hc; eval key_strip
set key center center horizontal maxrows 1 samplen 3 width 1 box noopaque  # drawn once (an opaque key is drawn twice)
plot for [i=1:words(ths)] NaN with linespoints lt i title sprintf('θ = %s', thn(word(ths, i)))
unset multiplot
