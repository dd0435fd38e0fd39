# Atlas of the heat equation (thesis Tables 4.5-4.7): relative error against the wall time of
# all K steps of a run, one panel per Δt rule (4.5: 0.0025 h², 4.6: 0.5 h², 4.7: 0.5 h);
# point type = weight, dash pattern = θ.  The heat runs record no pair count, so there is no
# pairs panel.  Series that blew up are not in the atlas.  Columns are addressed by name
# (rel_error, time_s, weight, theta, dt_nominal of atlas_heat.tsv).
load 'figures/style.gp'
set terminal svg size 1250,430 dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/atlas_heat.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ws = uniq('weight'); ths = uniq('theta'); dts = uniq('dt_nominal'); nt = words(ths)
pos(list, x) = sum [k=1:words(list)] (word(list, k) eq x ? k : 0)
widx(w) = pos(ws, w); tidx(t) = pos(ths, t)  # the same weight/θ keep their style in every panel
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w
set format x '10^{%T}'
set format y '10^{%T}'
set ylabel 'relative error (4.2), ℓ^∞(0,T; ℓ^2(Ω_H))'
set xlabel 'wall time of the run [s]'
set key outside right font ',9' samplen 3 noenhanced
set multiplot layout 1,words(dts) title 'Thesis Tables 4.5-4.7 (heat): accuracy against cost'
do for [d=1:words(dts)] {
  set title 'Δt = '.word(dts, d) noenhanced
  if (d < words(dts)) { unset key } else { set key }
  # The (weight, θ) series present under this Δt rule (θ = 0 is absent where it blew up).
  cs = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"dt_nominal\"]==\"%s\" { print $c[\"weight\"], $c[\"theta\"] }' '%s' | sort -u | tr '\n' ' '", word(dts, d), f))
  plot for [i=1:words(cs)/2] \
       rows_named(f, sprintf('$c["weight"]=="%s" && $c["theta"]=="%s" && $c["dt_nominal"]=="%s"', word(cs, 2*i-1), word(cs, 2*i), word(dts, d))) \
       using (column("time_s")):(column("rel_error")) with linespoints lt widx(word(cs, 2*i-1)) dt tidx(word(cs, 2*i)) \
       title sprintf('%s, θ = %s', sh(word(cs, 2*i-1)), word(cs, 2*i))
}
unset multiplot
