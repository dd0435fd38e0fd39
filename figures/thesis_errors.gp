# Shared body of the thesis' error figures (4.3, 4.5, 4.6, 4.7): relative error against h,
# one panel per test function (Case 1, Case 2).  The caller sets
#   f (data file), OP (operator column value), W (weights, space-separated), L (labels,
#   space-separated), S (the theoretical rates, space-separated), SW (for each rate, the index
#   in W of the weight whose series carries its triangle; default 1), T (title), P (the
#   published long-format table).
# Solid lines: the printed h and Voronoi volumes (the reproduction); dashed: the scaled h
# (Voronoi); dotted: the printed h with uniform volumes |Ω_H|/N.  Each triangle (a theoretical
# rate) sits under the two finest points of its weight's reproduction series; the
# thick grey segments start at the finest point of each reproduction series and rise with the
# PUBLISHED rate of that weight and case over the last interval: where the rate agrees, the
# segment lies on the data.  Columns are addressed by name (the data file's header).
load 'figures/style.gp'
set terminal svg size 1100,760 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set datafile columnheaders
set xlabel 'h'
set ylabel (OP eq 'grad' ? 'relative error, max over particles in Ω of |∇v − ∇_hv| (Euclidean)' : \
            OP eq 'lap' ? 'relative error, max over particles in Ω of |Δv − Δ_hv|' : \
            'relative error, max over particles in Ω of |v − Π_hv|')
stats f using (column("h")) nooutput
xlo = STATS_min * 0.8; xhi = STATS_max * 1.25
eval pow2_xtics
# Only the series a table has: Table 4.1 has no scaled reading.
nscaled = int(system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"h_reading\"]==\"scaled\"' '%s' | wc -l", f)))
set key outside below maxrows 4 box font ',10' samplen 2
label(i) = word(L, i)
if (!exists("SW")) SW = '1'

opn(i) = word('6 4 8 10 12 14 6 8 10', i) + 0  # open point types for uniform volumes
sel(r, v, w, c) = rows_named(f, sprintf('$c["h_reading"]=="%s" && $c["volumes"]=="%s" && $c["weight"]=="%s" && $c["operator"]=="%s" && $c["function"]=="%s"', r, v, w, OP, c))
# The published rate of (weight, case) from P (NaN if the table has none).
pub(w, c) = real(system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"weight\"]==\"%s\" && $c[\"function\"]==\"%s\" && (!(\"operator\" in c) || $c[\"operator\"]==\"%s\") { print $c[\"numerical\"]; f=1; exit } END { if (!f) print \"NaN\" }' '%s'", w, c, OP, P)))
set multiplot layout 1,2 title T
SCALED = nscaled > 0 ? "for [i=1:words(W)] sel('scaled', 'voronoi', word(W,i), c) using (column('h')):(column('rel_error')) with linespoints lt i dt 2 title sprintf('%s (scaled h, Voronoi)', label(i))," : ""
do for [c in "case1 case2"] {
  set title (c eq "case1" ? "Case 1: (x−½)^4+(y−½)^4" : "Case 2: sin 2π(x+y)")
  unset object; unset label; unset arrow
  # The published rate of each weight, from the finest point of its reproduction series.
  do for [i=1:words(W)] {
    ANCHOR = sel('printed', 'voronoi', word(W,i), c)
    stats ANCHOR using (column('h')) name 'PX' nooutput
    stats ANCHOR using (column('h') > PX_min ? column('h') : NaN) name 'PX2' nooutput
    stats ANCHOR using (column('h') == PX_min ? column('rel_error') : NaN) name 'PY' nooutput
    p = pub(word(W,i), c)
    if (p == p) {
      set arrow from PX_min, PY_min to PX2_min, PY_min * (PX2_min / PX_min)**p nohead lw 6 lc rgb '#bbbbbb' back
    }
  }
  do for [k=1:words(S)] {
    ANCHOR = sel('printed', 'voronoi', word(W, word(SW, k) + 0), c)
    eval anchored_triangle(word(S, k) + 0, 'slope '.word(S, k))
  }
  plot for [i=1:words(W)] sel("printed", "voronoi", word(W,i), c) using (column('h')):(column('rel_error')) with linespoints lt i dt 1 title sprintf('%s (printed h, Voronoi)', label(i)), \
       @SCALED \
       for [i=1:words(W)] sel("printed", "uniform", word(W,i), c) using (column('h')):(column('rel_error')) with linespoints lt i dt 3 pt opn(i) title sprintf('%s (printed h, |Ω_H|/N)', label(i)), \
       NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate, from the finest point'
}
unset multiplot
