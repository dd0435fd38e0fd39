# Atlas of a thesis truncation table (4.1-4.3), Case 2 (sin 2π(x+y)): relative ℓ^∞(Ω) error
# against wall time (left) and against neighbour pairs (right), one row per (operator, weight),
# named on the error axis.  Time = the fused pass of the (h reading, volumes, level) slice —
# shared by every weight of the slice, not apportioned — plus the Voronoi volumes where they
# are used.  In each panel one series per (volume choice, h reading), with the same line style
# in every panel and one legend, in a strip below the panels.  The panels of a column share
# the cost axis (labelled under the bottom row), and the panels of an operator share the error
# axis (labelled in the left column), so the weights compare down a column.
# Set `table` (e.g. '4_1') before loading.
# Columns are addressed by name (rel_error, time_s, pairs, operator, function, volumes,
# h_reading, weight of atlas_thesis_table<t>.tsv).
# Drawn at print size: 760 px wide (the A4 text width is 703 px), 14 px text, so nothing prints
# below 8 pt; panels placed by hand with panel_at.
load 'figures/style.gp'
f = datadir.'/atlas_thesis_table'.table.'.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"function\"]==\"case2\" { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ops = uniq('operator'); ws = uniq('weight'); vols = uniq('volumes'); hs = uniq('h_reading')
nop = words(ops); nw = words(ws); nv = words(vols); nh = words(hs)
# One flat index over (volumes, h reading) per panel: line type of the setting.
V(i) = (i - 1) / nh + 1; R(i) = (i - 1) % nh + 1
nrow = nop * nw
# Rows of at most 200 px, the whole no taller than 1000 px (at 703 px wide it prints on one A4
# page, 273 mm high inside the margins), 22 px between rows (the tick labels of neighbouring
# rows do not touch), a wider gap between the rows of two operators.
W = 760; GYo = 34.0; rowh = (805 - (nop - 1) * GYo) / nrow < 200 ? (805 - (nop - 1) * GYo) / nrow : 200
Hc = rowh * nrow + (nop - 1) * GYo + 195
set terminal svg size W,Hc dynamic enhanced font 'Helvetica,14' background rgb 'white'
set output out
set datafile columnheaders
set format y '10^{%T}'
unset key
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w eq 'quadratic_spike' ? 'quadr. spike' : \
        w eq 'cubic_spike' ? 'cubic spike' : w eq 'cubic_bspline' ? 'cubic B-spl.' : \
        w eq 'quintic_bspline' ? 'quintic B-spl.' : w
vname(v) = v eq 'voronoi' ? 'Voronoi' : '|Ω_H|/N'
# Decade-aligned ranges (computed before any range is set: stats applies the current ranges).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
xcol(c) = c == 1 ? "time_s" : "pairs"
csel = rows_named(f, '$c["function"]=="case2"')
stats csel using (column("time_s")) name 'TX' nooutput
stats csel using (column("pairs")) name 'PX' nooutput
set multiplot title 'Thesis Table '.table[1:1].'.'.table[3:3].': relative ℓ^∞(Ω) error against cost, Case 2' font ',15'
PL = 100.0 / W; PR = 1 - 20.0 / W; GX = 46.0 / W; PW = (PR - PL - GX) / 2
PT = 1 - 80.0 / Hc; GY = 22.0 / Hc; PH = rowh / Hc - GY
row = 0
do for [k=1:nop] {
  osel = rows_named(f, sprintf('$c["operator"]=="%s" && $c["function"]=="case2"', word(ops, k)))
  set autoscale xy
  stats osel using (column("rel_error")) name 'SY' nooutput
  do for [r=1:nw] {
    row = row + 1
    do for [c=1:2] {
      eval panel_at(c, row)
      # Rows of the next operator start a little lower.
      eval sprintf("set tmargin at screen %.17g; set bmargin at screen %.17g", PT - (row - 1) * (PH + GY) - (k - 1) * GYo / Hc, PT - (row - 1) * (PH + GY) - (k - 1) * GYo / Hc - PH)
      if (c == 1) { set xrange [lo(TX_min):hi(TX_max)] } else { set xrange [lo(PX_min):hi(PX_max)] }
      set yrange [lo(SY_min):hi(SY_max)]
      # Column heads over the first row; the row's operator and weight name its error axis.
      if (row == 1) { set title (c == 1 ? 'error against wall time' : 'error against pair interactions') } else { unset title }
      set format x (row == nrow ? '10^{%T}' : '')
      set xlabel (row < nrow ? '' : c == 1 ? 'wall time of the slice (pass + Voronoi) [s]' : 'neighbour pairs of the level') offset 0,0.4
      set format y (c == 1 ? '10^{%T}' : '')
      set ylabel (c == 1 ? sprintf("%s, %s\nrelative error", word(ops, k), sh(word(ws, r))) : '')
      plot for [i=1:nv*nh] \
           rows_named(f, sprintf('$c["operator"]=="%s" && $c["function"]=="case2" && $c["weight"]=="%s" && $c["volumes"]=="%s" && $c["h_reading"]=="%s"', \
                                 word(ops, k), word(ws, r), word(vols, V(i)), word(hs, R(i)))) \
           using (column(xcol(c))):(column("rel_error")) with linespoints lt i notitle
    }
  }
}
# The key: under the panels, one entry per (volume choice, h reading), as in every panel.
KEY_TOP = 40.0 / Hc; eval key_strip
set key center center horizontal maxrows 1 samplen 2 width -5 box noopaque  # drawn once (an opaque key is drawn twice)
plot for [i=1:nv*nh] NaN with linespoints lt i title sprintf('%s, h %s', vname(word(vols, V(i))), word(hs, R(i)))
unset multiplot
