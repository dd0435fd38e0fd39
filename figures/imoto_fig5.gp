# Imoto Figure 5 (a)(b)(c): relative l-inf errors of the interpolant, gradient and Laplacian
# against h for m = 1, 3, 5 and the weights of Sec. 5.  The document draws the nine curves of
# an operator in one panel; here each operator is a column and each m a row, three weights per
# panel, so that every curve can be told apart in greyscale.  Triangles: Theorem 3's rates,
# under the two finest points of the series they describe (weight 1; weight 3 at m = 5, whose
# Hypothesis 1 order n = 3 raises the rate), labelled on their left: the m = 3, 5 rows start
# their h axis far enough left of the finest point for the label.  Grey segments: the PUBLISHED rate of Table 1 for each curve, over
# its last interval just below the data (where the rate agrees, parallel to them; m = 1 rows
# claim no convergence).  Rows are 80 px apart, so a panel title clears the tick labels of
# the panel above.
# Columns are addressed by name (level, m, weight, h, rel_error of imoto_fig5_table1.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing
# prints below 8 pt; panels placed by hand, each row on the h range of its m (the data fill
# the axis), one legend below the panels (the line type is the weight's index in every panel).
load 'figures/style.gp'
W = 760; Hc = 700
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
TRI_FONT = ',14'
set output out
set datafile columnheaders
f = datadir.'/imoto_fig5_table1.tsv'
P = 'tables/published/imoto_table1.tsv'
unset key
set multiplot title "Imoto Figure 5: relative ℓ^∞(Ω) errors against h" font ',15'
ops = "interpolant gradient laplacian"
w1 = "Pi1 Grad1 Lap1"; w2 = "Pi2 Grad2 Lap2"; w3 = "Pi3 Grad3 Lap3"
sym = "Π ∇ Δ"
# Theorem 3 rates per operator at m = 3 and m = 5 (n = 1 weights; the n = 3 weight at m = 5).
s3 = "2 2 1"; s5 = "2 2 2"; s5h = "4 4 3"
sel(m, w) = rows_named(f, sprintf('$c["m"]==%s && $c["weight"]=="%s"', m, w))
pub(w, m) = published_rate(P, sprintf('$c["weight"]=="%s" && $c["m"]==%s', w, m))
weight_of(j, k) = word(j == 1 ? w1 : j == 2 ? w2 : w3, k)
# Panel boxes (screen fractions): columns = operators, rows = m (top to bottom 1, 3, 5).
PL = 72.0 / W; PR = 1 - 12.0 / W; GX = 58.0 / W; PW = (PR - PL - 2 * GX) / 3
PT = 1 - 62.0 / Hc; PB = 115.0 / Hc; GY = 80.0 / Hc; PH = (PT - PB - 2 * GY) / 3
row = 0
do for [m in "1 3 5"] {
  row = row + 1
  stats rows_named(f, sprintf('$c["m"]==%s', m)) using (column("h")) name 'HX' nooutput
  do for [k=1:3] {
    eval panel_at(k, row)
    set title sprintf('(%s) %s, m = %s', substr("abc", k, k), word(ops, k), m) offset 0,-0.6
    set ylabel (k == 1 ? 'relative error' : '')
    if (row == 3) { set xlabel 'h' offset 0,0.5 } else { unset xlabel }
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
    set xrange [HX_min / (m eq "1" ? 1.6 : 2.6) : HX_max * 1.25]
    # m = 1 spans two decades of h; m = 3, 5 less than one: ticks at factors of 2 there.
    if (m eq "1") { set format x '10^{%L}'; set xtics autofreq } else { set format x '%g'; set xtics (0.01, 0.02, 0.04, 0.08) }
    if (k < 3) { set yrange [1e-5:1]; set ytics 100 } else { set yrange [1e-4:1e3]; set ytics 100 }
    plot for [j=1:3] sel(m, weight_of(j, k)) using (column("h")):(column("rel_error")) \
           with linespoints lt j notitle
  }
}
# The key: one row under the panels.
KEY_TOP = 45.0 / Hc; eval key_strip
set key center center horizontal maxrows 1 samplen 1.5 width -3 box noopaque  # drawn once (an opaque key is drawn twice)
plot for [j=1:3] NaN with linespoints lt j title sprintf('weight %d (Π%d, ∇%d, Δ%d)', j, j, j, j), \
     NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'
unset multiplot
