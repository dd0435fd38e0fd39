# Shared body of the thesis' error figures (4.3, 4.5, 4.6, 4.7): relative error against h,
# one panel per test function (Case 1, Case 2).  The caller sets
#   f (data file), OP (operator column value), W (weights, space-separated), L (labels,
#   '|'-separated), S (reference slopes, space-separated: the theoretical rates), T (title).
# Solid lines: the printed h and Voronoi volumes (the reproduction); dashed: the scaled h
# (Voronoi); dotted: the printed h with uniform volumes |Ω_H|/N.  Triangles: slopes S.
load 'figures/style.gp'
set terminal svg size 1100,720 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set output out
set xlabel 'h'
set ylabel 'relative error'
# h axis: the file's range of h, widened (triangles on the left), labelled in half powers of 2.
stats f using 8 nooutput
xlo = STATS_min * 0.45; xhi = STATS_max * 1.25  # room on the left for the slope triangles
eval pow2_xtics
# Only the series a table has: Table 4.1 has no scaled reading (one reading), so the scaled
# stats and plot clauses are skipped rather than left to warn about files with no points.
nscaled = int(system(sprintf("awk -F'\t' '$1==\"scaled\"' '%s' | wc -l", f)))
set key outside below maxrows 4 box font ',9' samplen 2
label(i) = word(L, i)
# Uniform volumes: the open version of the weight's point type (black-and-white readable).
opn(i) = word('6 4 8 10 12 14 6 8 10', i) + 0
sel(r, v, w, c) = rows(f, sprintf('$1=="%s" && $2=="%s" && $4=="%s" && $5=="%s" && $6=="%s"', r, v, w, OP, c))
set multiplot layout 1,2 title T
# The scaled-h clause as a macro, empty where the table has no scaled reading.
SCALED = nscaled > 0 ? "for [i=1:words(W)] sel('scaled', 'voronoi', word(W,i), c) using 8:13 with linespoints lt i dt 2 title sprintf('%s (scaled h, Voronoi)', label(i))," : ""
do for [c in "case1 case2"] {
  set title (c eq "case1" ? "Case 1: (x−½)^4+(y−½)^4" : "Case 2: sin 2π(x+y)")
  if (nscaled > 0) {
    stats rows(f, sprintf('$5=="%s" && $6=="%s" && $1=="scaled"', OP, c)) using 8:13 nooutput
    hs = STATS_min_x
  }
  stats rows(f, sprintf('$5=="%s" && $6=="%s"', OP, c)) using 8:13 nooutput
  if (!exists("hs") || hs <= 0) { hs = STATS_min_x }
  unset object; unset label
  n = words(S)
  do for [k=1:n] {
    eval triangle(hs*0.55, STATS_min_y*(6.0**(k-1)), 1.4, word(S,k)+0, sprintf('%s', word(S,k)))
  }
  plot for [i=1:words(W)] sel("printed", "voronoi", word(W,i), c) using 8:13 with linespoints lt i dt 1 title sprintf('%s (printed h, Voronoi)', label(i)), \
       @SCALED \
       for [i=1:words(W)] sel("printed", "uniform", word(W,i), c) using 8:13 with linespoints lt i dt 3 pt opn(i) title sprintf('%s (printed h, |Ω_H|/N)', label(i))
  undefine hs
}
unset multiplot
