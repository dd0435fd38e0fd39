# imoto Figure 5 (a)(b)(c): relative l-inf errors of the interpolant, gradient and Laplacian
# against h for m = 1, 3, 5 and the weights of Sec. 5; triangles show Theorem 3's rates.
# Columns are addressed by name (level, m, weight, h, rel_error of imoto_fig5_table1.tsv).
load 'figures/style.gp'
set terminal svg size 1500,680 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
f = datadir.'/imoto_fig5_table1.tsv'
set xlabel 'h'
set ylabel 'relative error'
set format x '10^{%L}'
set key outside below maxrows 3 font ',10'
set multiplot layout 1,3
ops = "interpolant gradient laplacian"
w1 = "Pi1 Grad1 Lap1"; w2 = "Pi2 Grad2 Lap2"; w3 = "Pi3 Grad3 Lap3"
lab = "(a)~interpolant (b)~gradient (c)~Laplacian"
sym = "Π ∇ Δ"
# Theorem 3 slopes per panel at m = 3 and m = 5 (n = 1 weights; n = 3 weights at m = 5).
s3 = "2 2 1"; s5 = "2 2 2"; s5h = "4 4 3"
sel(m, w) = rows_named(f, sprintf('$c["m"]==%s && $c["weight"]=="%s"', m, w))
do for [k=1:3] {
  set title sprintf('(%s) %s', substr("abc", k, k), word(ops, k))
  unset object; unset label
  # Slope triangles (Theorem 3's rates) under the two finest points of the series they
  # describe: weight 1 at m = 3 and m = 5, weight 3 at m = 5.  Before the ranges are set.
  set autoscale xy
  ANCHOR = sel("3", word(w1, k)); eval anchored_triangle(real(word(s3, k)), 'm=3: '.word(s3, k))
  ANCHOR = sel("5", word(w1, k)); eval anchored_triangle(real(word(s5, k)), 'm=5: '.word(s5, k))
  ANCHOR_DROP = 0.3; ANCHOR = sel("5", word(w3, k)); eval anchored_triangle(real(word(s5h, k)), sprintf('m=5, %s3: %s', word(sym,k), word(s5h, k)))
  ANCHOR_DROP = 0.7
  set xrange [2e-3:0.1]
  if (k < 3) { set yrange [1e-4:1] } else { set yrange [1e-3:1e3] }
  plot for [m in "1 3 5"] for [j=1:3] \
       sel(m, word(j==1 ? w1 : j==2 ? w2 : w3, k)) using (column("h")):(column("rel_error")) \
       with linespoints lt (m eq "1" ? 0 : m eq "3" ? 3 : 6) + j \
       title sprintf('%s%d, m = %s', word(sym, k), j, m)
}
unset multiplot
