# Imoto Figure 5 (a)(b)(c): relative l-inf errors of the interpolant, gradient and Laplacian
# against h for m = 1, 3, 5 and the weights of Sec. 5.  The document draws the nine curves of
# an operator in one panel; here each operator is a column and each m a row, three weights per
# panel, so that every curve can be told apart in greyscale.  Triangles: Theorem 3's rates,
# under the two finest points of the series they describe (weight 1; weight 3 at m = 5, whose
# Hypothesis 1 order n = 3 raises the rate).  Grey segments: the PUBLISHED rate of Table 1
# for each curve, drawn from its finest point over the last interval (where the rate agrees,
# the segment lies on the data; m = 1 rows claim no convergence).
# Columns are addressed by name (level, m, weight, h, rel_error of imoto_fig5_table1.tsv).
load 'figures/style.gp'
set terminal svg size 1500,1450 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/imoto_fig5_table1.tsv'
P = 'tables/published/imoto_table1.tsv'
set xlabel 'h'
set format x '10^{%L}'
set key bottom left box opaque font ',10' samplen 2
set multiplot layout 3,3 title 'Imoto Figure 5: relative ℓ^∞(Ω) errors (max over particles in Ω; Euclidean length for ∇) against h'
ops = "interpolant gradient laplacian"
w1 = "Pi1 Grad1 Lap1"; w2 = "Pi2 Grad2 Lap2"; w3 = "Pi3 Grad3 Lap3"
sym = "Π ∇ Δ"
# Theorem 3 rates per operator at m = 3 and m = 5 (n = 1 weights; the n = 3 weight at m = 5).
s3 = "2 2 1"; s5 = "2 2 2"; s5h = "4 4 3"
sel(m, w) = rows_named(f, sprintf('$c["m"]==%s && $c["weight"]=="%s"', m, w))
pub(w, m) = published_rate(P, sprintf('$c["weight"]=="%s" && $c["m"]==%s', w, m))
weight_of(j, k) = word(j == 1 ? w1 : j == 2 ? w2 : w3, k)
do for [m in "1 3 5"] {
  do for [k=1:3] {
    set title sprintf('(%s) %s, m = %s', substr("abc", k, k), word(ops, k), m)
    set ylabel (k == 1 ? 'relative error' : '')
    unset object; unset label; unset arrow
    set autoscale xy
    # Published rates, from the finest point of each curve.
    do for [j=1:3] {
      ANCHOR = sel(m, weight_of(j, k))
      p = pub(weight_of(j, k), m)
      if (p == p) { eval published_segment(p) }
    }
    # Theorem 3's rates (none at m = 1, where the document claims no convergence).
    if (m ne "1") {
      ANCHOR = sel(m, word(w1, k))
      eval anchored_triangle(real(word(m eq "3" ? s3 : s5, k)), 'slope '.word(m eq "3" ? s3 : s5, k))
      if (m eq "5") {
        ANCHOR_DROP = (k == 3 ? 0.08 : 0.3); ANCHOR = sel(m, word(w3, k))
        eval anchored_triangle(real(word(s5h, k)), sprintf('%s3: %s', word(sym, k), word(s5h, k)))
        ANCHOR_DROP = 0.7
      }
    }
    set xrange [5e-4:0.1]
    if (k < 3) { set yrange [1e-5:1] } else { set yrange [1e-4:1e3] }
    plot for [j=1:3] sel(m, weight_of(j, k)) using (column("h")):(column("rel_error")) \
           with linespoints lt j title sprintf('%s%d', word(sym, k), j), \
         NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'
  }
}
unset multiplot
