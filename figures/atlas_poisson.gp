# Atlas of the discrete Poisson problem (thesis Table 4.4): relative error against the wall
# time of assembly + CG solve (left) and the matrix nonzeros (right), per weight (point type)
# and h rule (dash pattern).  Columns are addressed by name (rel_error, time_s, pairs
# (= nonzeros), h_rule, weight of atlas_poisson.tsv).
load 'figures/style.gp'
set terminal svg size 1050,430 dynamic enhanced font 'Helvetica,11' background rgb 'white'
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
set ylabel 'max_Ω|ũ − U| / max_Ω|ũ|  (ℓ^∞(Ω), relative)'
set key outside right font ',9' samplen 3 noenhanced
set multiplot layout 1,2 title 'Thesis Table 4.4 (Poisson): accuracy against cost'
do for [c=1:2] {
  set title sprintf('error against %s', c == 1 ? 'wall time' : 'matrix nonzeros')
  set xlabel (c == 1 ? 'assembly + solve [s]' : 'nonzeros of the matrix')
  if (c == 1) { unset key } else { set key }
  plot for [i=0:words(ws)*nh-1] rows_named(f, sprintf('$c["weight"]=="%s" && $c["h_rule"]=="%s"', word(ws, J(i)), word(hs, R(i)))) \
       using (column(c == 1 ? "time_s" : "pairs")):(column("rel_error")) with linespoints lt J(i) dt R(i) \
       title sprintf('%s, h rule %s', sh(word(ws, J(i))), word(hs, R(i)))
}
unset multiplot
