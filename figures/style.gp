# One style for every figure of the report: readable in black and white
# (point types and dash patterns carry the distinction, colour only helps).
# Print size: the report shows a figure 623 px wide (the A4 text width of 703 px less the
# <figure> margins), so on a 760 px canvas 14 px text prints at 8.6 pt and 12 px at 7.4 pt,
# below the 8 pt that tests/report/browser_check.sh asks: figures drawn for print use 14 px.
set terminal svg size 640,480 dynamic enhanced font 'Helvetica,12' background rgb 'white'
set key top left box opaque samplen 3
set grid lc rgb '#dddddd'
set format y '10^{%L}'
set logscale xy
set linetype 1 lc rgb '#000000' dt 1 pt 7 ps 0.8 lw 1.5
set linetype 2 lc rgb '#1f4e9c' dt 2 pt 5 ps 0.8 lw 1.5
set linetype 3 lc rgb '#b22222' dt 3 pt 9 ps 0.9 lw 1.5
set linetype 4 lc rgb '#2e7d32' dt 4 pt 11 ps 0.9 lw 1.5
set linetype 5 lc rgb '#6a1b9a' dt 5 pt 13 ps 0.9 lw 1.5
# gnuplot has five dash types (dt 6-9 would repeat dt 1-4, so that lt 7 drawn with lines looks
# like lt 2 in grey): linetypes 6-9 get dash patterns of their own.
set linetype 6 lc rgb '#e65100' dt (10,4) pt 4 ps 0.8 lw 1.5
set linetype 7 lc rgb '#555555' dt (10,3,3,3) pt 6 ps 0.8 lw 1.5
set linetype 8 lc rgb '#00838f' dt (3,2) pt 8 ps 0.8 lw 1.5
set linetype 9 lc rgb '#795548' dt (12,3,1,3,1,3,1,3) pt 10 ps 0.8 lw 1.5
set datafile separator "\t"
set datafile commentschars "#"
# Draw a reference-slope triangle of slope s with its lower-left corner at (x0, y0),
# spanning a factor f in x: call   eval triangle(x0, y0, f, s, 'label')
# The label sits left of the triangle's lower-left corner, so neighbouring triangles do not
# share label space; with TRI_BELOW = 1 it sits centred under the triangle instead (a triangle
# at the left edge of a panel, whose label would cross the axis and its tick labels).
# TRI_FONT: the label's font (a figure drawn at print size sets it to its text size).
TRI_FONT = ',10'
TRI_BELOW = 0
triangle(x0, y0, f, s, lab) = sprintf("set object polygon from %g,%g to %g,%g to %g,%g to %g,%g fs empty border lc rgb '#000000'; set label '%s' at %g,%g %s font '%s'", \
  x0, y0, x0*f, y0, x0*f, y0*f**s, x0, y0, lab, TRI_BELOW ? x0*sqrt(f) : x0/1.06, TRI_BELOW ? y0/1.6 : y0, TRI_BELOW ? 'center' : 'right', TRI_FONT)
# A log-2 x axis labelled with powers of 2 in half steps, for abscissae (such as h) that span
# less than a decade, where '10^{%L}' would leave a single label.  Set the range first:
#   xlo = 0.09; xhi = 0.22; eval pow2_xtics
pow2_xtics = "set logscale x 2; set xrange [xlo:xhi]; set xtics ('' xlo); do for [k=ceil(2*log(xlo)/log(2)):floor(2*log(xhi)/log(2))] { set xtics add (sprintf('2^{%g}', k/2.0) 2**(k/2.0)) }"
# Data rows chosen by column NAME, header kept, for `set datafile columnheaders` and
# column("name") in `using`:   plot rows_named(f, '$c["variant"]=="seed1"') using (column("h")):(column("rel_error"))
# (filtering outside gnuplot keeps lines unbroken where other rows are interleaved).
rows_named(f, cond) = sprintf("< awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; print; next } (%s)' '%s'", cond, f)
# The same rows, but only where at least three of them hold a number in column COL (else the
# header alone): the line of a series, which is not drawn through two points (figure rules).
# Plot the series' points from rows_named and its line from rows_trend:
#   plot rows_named(f, c) using … with points lt 1 title 'x', rows_trend(f, c, 'y') using … with lines lt 1 notitle
rows_trend(f, cond, col) = sprintf("< awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; print; next } (%s) && $c[\"%s\"] ~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/ { r[++n] = $0 } END { for (i = 1; n >= 3 && i <= n; i++) print r[i] }' '%s'", cond, col, f)
# A slope-s triangle under the two finest points (smallest h) of the series in the string
# variable ANCHOR (a rows_named(...) source; needs `set datafile columnheaders`; call before any
# xrange/yrange is set, which stats would apply):   ANCHOR = sel(1, 1); eval anchored_triangle(2, 'slope 2')
# The two finest points of ANCHOR: AX_min (smallest h), AX2_min (the next), AY_min (its error).
finest_points = "stats ANCHOR using (column('h')) name 'AX' nooutput; " . \
  "stats ANCHOR using (column('h') > AX_min ? column('h') : NaN) name 'AX2' nooutput; " . \
  "stats ANCHOR using (column('h') == AX_min ? column('rel_error') : NaN) name 'AY' nooutput; "
anchored_triangle(s, lab) = finest_points . \
  sprintf("eval triangle(AX_min, AY_min * ANCHOR_DROP, AX2_min / AX_min, %g, '%s')", s, lab)
# A published rate p drawn beside the series in ANCHOR: a thick grey segment with slope p over
# the documents' own level pair (the `# rate_levels` line of the published file P, the pair the
# rate belongs to), PUB_DROP below the series' point at the finer of them (where the rate agrees
# it runs parallel to the data just under them, not hidden beneath the markers).  A series that
# lacks either level (a profile that stops short of the documents') gets it over its two
# finest points instead.  Legend entry: NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'.
#   ANCHOR = sel(...); p = published_rate(P, '$c["weight"]=="Pi1"'); if (p == p) { eval published_segment(p) }
published_segment(p) = finest_points . \
  "DL = doc_levels(P); DL1 = DL[1:strstrt(DL, ',') - 1]; DL2 = DL[strstrt(DL, ',') + 1:]; " . \
  "PX1 = anchor_at(DL1, 'h'); PX2 = anchor_at(DL2, 'h'); PY2 = anchor_at(DL2, 'rel_error'); " . \
  "if (!(PX1 == PX1 && PX2 == PX2 && PY2 == PY2)) { PX1 = AX2_min; PX2 = AX_min; PY2 = AY_min }; " . \
  sprintf("set arrow from PX2, PY2 * PUB_DROP to PX1, PY2 * PUB_DROP * (PX1 / PX2)**%.17g nohead lw 6 lc rgb '#bbbbbb' back", p)
# The documents' level pair of a published file ("7,8"; "," where it names none).
doc_levels(P) = system(sprintf("awk -F' = ' '$1 == \"# rate_levels\" { print $2; f = 1; exit } END { if (!f) print \",\" }' '%s'", P))
# Column `col` of the series in ANCHOR at level `lv` (a number as text); NaN where it has none.
anchor_at(lv, col) = real(system(sprintf("%s | awk -F'\t' '!h++ { for (i=1;i<=NF;i++) c[$i]=i; next } \"%s\" != \"\" && $c[\"level\"] == \"%s\" { print $c[\"%s\"]; f = 1; exit } END { if (!f) print \"NaN\" }'", ANCHOR[3:], lv, lv, col)))
PUB_DROP = 0.55  # factor in y between the finest point and the published-rate segment
# The `numerical` column of the first row of a published long-format table P that satisfies an
# awk condition on its named columns (as rows_named); NaN when no row does.
published_rate(P, cond) = real(system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } (%s) { print $c[\"numerical\"]; f=1; exit } END { if (!f) print \"NaN\" }' '%s'", cond, P)))
ANCHOR_DROP = 0.7  # how far below the finest point the triangle sits (factor in y)
# A multiplot's key alone in a strip along the bottom of the canvas, up to screen height
# KEY_TOP: call after the panels, then `set key …` and plot NaN series for the entries:
#   KEY_TOP = 0.09; eval key_strip; set key center center horizontal maxrows 1 box noopaque
key_strip = "unset object; unset arrow; unset label; unset title; unset xlabel; unset ylabel; " . \
  "unset border; unset tics; unset grid; unset logscale; set xrange [0:1]; set yrange [0:1]; " . \
  "set lmargin at screen 0.02; set rmargin at screen 0.98; set bmargin at screen 0.0; set tmargin at screen KEY_TOP"
# Panels placed by hand on a grid (a key strip or per-panel titles need more room than `set
# multiplot layout` leaves): the panel in column i, row j (from the top) spans PL + (i-1)(PW+GX)
# across PW and PT - (j-1)(PH+GY) down PH, in screen fractions; the script sets those six.
#   eval panel_at(i, j); plot …
panel_at(i, j) = sprintf("set lmargin at screen %.17g; set rmargin at screen %.17g; " . \
  "set tmargin at screen %.17g; set bmargin at screen %.17g", PL + (i - 1) * (PW + GX), \
  PL + (i - 1) * (PW + GX) + PW, PT - (j - 1) * (PH + GY), PT - (j - 1) * (PH + GY) - PH)
