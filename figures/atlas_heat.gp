# Atlas of the heat equation (thesis Tables 4.5-4.7): relative error against the wall time of
# all K steps of a run, one row per weight and one column per Δt rule (4.5: 0.0025 h²,
# 4.6: 0.5 h², 4.7: 0.5 h); in each panel one series per θ (line style = θ, the same in every
# panel).  The panels of a column share both axes, so the weights compare down a column.  The
# heat runs record no pair count, so there is no pairs panel.  Series that blew up are not in
# the atlas.  Columns are addressed by name (rel_error, time_s, weight, theta, dt_nominal of
# atlas_heat.tsv).
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
W = 330 * nd + 230; H = 330 * nw + 130
set terminal svg size W,H dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
set format x '10^{%T}'
set format y '10^{%T}'
set key outside right top font ',10' samplen 3 noenhanced
# Decade-aligned range of column c over the rows of the Δt rule d (before any range is set).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
set multiplot layout nw,nd margins 80.0/W,1 - 150.0/W,60.0/H,1 - 60.0/H spacing 60.0/W,80.0/H \
    title 'Thesis Tables 4.5-4.7 (heat): accuracy against cost'
do for [r=1:nw] {
  do for [d=1:nd] {
    set autoscale xy
    dsel = rows_named(f, sprintf('$c["dt_nominal"]=="%s"', word(dts, d)))
    stats dsel using (column("time_s")) name 'SX' nooutput
    stats dsel using (column("rel_error")) name 'SY' nooutput
    set xrange [lo(SX_min):hi(SX_max)]
    set yrange [lo(SY_min):hi(SY_max)]
    set title sprintf('%s, Δt = %s', sh(word(ws, r)), word(dts, d)) noenhanced
    set xlabel (r == nw ? 'wall time of the run [s]' : '')
    set ylabel (d == 1 ? 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))' : '')
    if (r == 1 && d == nd) { set key } else { unset key }
    # The θ present for this weight under this Δt rule (θ = 0 is absent where it blew up).
    cs = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"dt_nominal\"]==\"%s\" && $c[\"weight\"]==\"%s\" { print $c[\"theta\"] }' '%s' | sort -u | tr '\n' ' '", word(dts, d), word(ws, r), f))
    plot for [i=1:words(cs)] \
         rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["dt_nominal"]=="%s"', word(ws, r), word(cs, i), word(dts, d))) \
         using (column("time_s")):(column("rel_error")) with linespoints lt tidx(word(cs, i)) \
         title sprintf('θ = %s', thn(word(cs, i)))
  }
}
unset multiplot
