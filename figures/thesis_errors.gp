# Shared body of the thesis' error figures (4.3, 4.5, 4.6, 4.7): relative error against h.
# The caller sets
#   f (data file), OP (operator column value), W (weights, space-separated), L (labels,
#   space-separated), S (the theoretical rates, space-separated), SW (for each rate, the index
#   in W of the weight whose series carries its triangle; default 1), T (title), P (the
#   published long-format table).
# One panel per setting and test function, so that no panel holds more than one curve per
# weight: rows = the printed h with Voronoi volumes (the thesis' set-up), the scaled h with
# Voronoi volumes (where the table has that reading), the printed h with uniform volumes
# |Ω_H|/N (beyond the thesis); columns = Case 1, Case 2.  Each triangle (a theoretical rate)
# sits under the two finest points of its weight's series; in the thesis' settings a thick
# grey segment rises with the PUBLISHED rate of that weight and case over the documents' level
# pair (style.gp's published_segment): where the rate agrees, it lies on the data.
# Columns are addressed by name (the data file's header).  Drawn at print size: 760 px wide
# (the A4 text width is 703 px), every text 14 px (superscripts 11 px), so none prints below 8 pt; one legend, in
# the first panel.
load 'figures/style.gp'
set datafile columnheaders
set ylabel (OP eq 'grad' ? 'max_Ω |∇v − ∇_hv| / max_Ω |∇v|' : \
            OP eq 'lap' ? 'max_Ω |Δv − Δ_hv| / max_Ω |Δv|' : 'max_Ω |v − Π_hv| / max_Ω |v|')
stats f using (column("h")) nooutput
xlo = STATS_min * 0.8; xhi = STATS_max * 1.25
stats f using (column("rel_error")) nooutput
ylo = STATS_min / 4; yhi = STATS_max * 2
eval pow2_xtics
set yrange [ylo:yhi]
# Only the settings a table has: Table 4.1 has no scaled reading.
nscaled = int(system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"h_reading\"]==\"scaled\"' '%s' | wc -l", f)))
settings = nscaled > 0 ? "printed:voronoi scaled:voronoi printed:uniform" : "printed:voronoi printed:uniform"
nrow = words(settings)
set terminal svg size 760,(200 * nrow + 70) dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
TRI_FONT = ',14'
set key bottom right box opaque font ',14' samplen 2 spacing 0.9
label(i) = word(L, i)
if (!exists("SW")) SW = '1'
reading(s) = s[1:strstrt(s, ':') - 1]
volumes(s) = s[strstrt(s, ':') + 1:]
setting_name(s) = sprintf('%s h, %s', reading(s), volumes(s) eq 'voronoi' ? 'Voronoi V_i' : 'V_i = |Ω_H|/N')
sel(r, v, w, c) = rows_named(f, sprintf('$c["h_reading"]=="%s" && $c["volumes"]=="%s" && $c["weight"]=="%s" && $c["operator"]=="%s" && $c["function"]=="%s"', r, v, w, OP, c))
# The published rate of (weight, case) from P.
pub(w, c) = published_rate(P, sprintf('$c["weight"]=="%s" && $c["function"]=="%s" && (!("operator" in c) || $c["operator"]=="%s")', w, c, OP))
set multiplot layout nrow,2 title T."\nCase 1: (x−½)^4+(y−½)^4,  Case 2: sin 2π(x+y)" font ",15"
panel = 0
do for [s in settings] {
  do for [c in "case1 case2"] {
    r = reading(s); v = volumes(s)
    set title sprintf('%s: %s', c eq "case1" ? "Case 1" : "Case 2", setting_name(s))
    panel = panel + 1
    if (panel > 2 * nrow - 2) { set xlabel 'h' } else { unset xlabel }  # h under the last row only
    if (panel > 1) { unset key }
    unset object; unset label; unset arrow
    if (v eq 'voronoi') {
      do for [i=1:words(W)] {
        ANCHOR = sel(r, v, word(W,i), c)
        p = pub(word(W,i), c)
        if (p == p) { eval published_segment(p) }
      }
    }
    do for [k=1:words(S)] {
      ANCHOR = sel(r, v, word(W, word(SW, k) + 0), c)
      eval anchored_triangle(word(S, k) + 0, 'slope '.word(S, k))
    }
    plot for [i=1:words(W)] sel(r, v, word(W,i), c) using (column('h')):(column('rel_error')) \
           with linespoints lt i title label(i), \
         v eq 'voronoi' ? NaN : 1/0 with lines lw 6 lc rgb '#bbbbbb' title (v eq 'voronoi' ? 'published rate' : '')
  }
}
unset multiplot
