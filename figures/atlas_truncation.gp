# Atlas of a thesis truncation table (4.1-4.3), Case 2 (sin 2π(x+y)): relative error
# against wall time (left) and against neighbour pairs (right), one row per (operator,
# weight).  Time = the fused pass of the (h reading, volumes, level) slice — shared by every
# weight of the slice, not apportioned — plus the Voronoi volumes where they are used.  In each
# panel one series per (volume choice, h reading), with the same line style in every panel; the
# panels of an operator share both axes per column, so the weights compare down a column.
# Set `table` (e.g. '4_1') before loading.
# Columns are addressed by name (rel_error, time_s, pairs, operator, function, volumes,
# h_reading, weight of atlas_thesis_table<t>.tsv).
load 'figures/style.gp'
f = datadir.'/atlas_thesis_table'.table.'.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"function\"]==\"case2\" { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ops = uniq('operator'); ws = uniq('weight'); vols = uniq('volumes'); hs = uniq('h_reading')
nop = words(ops); nw = words(ws); nv = words(vols); nh = words(hs)
# One flat index over (volumes, h reading) per panel: line type of the setting.
V(i) = (i - 1) / nh + 1; R(i) = (i - 1) % nh + 1
nrow = nop * nw
# Rows of at most 250 px, and the whole no taller than 1420 px (it prints on one A4 page).
W = 1050; rowh = 1270 / nrow < 250 ? 1270 / nrow : 250; H = rowh * nrow + 150
set terminal svg size W,H dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
set format x '10^{%T}'
set format y '10^{%T}'
set key outside right top font ',10' samplen 3
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w eq 'quadratic_spike' ? 'quadr. spike' : \
        w eq 'cubic_spike' ? 'cubic spike' : w eq 'cubic_bspline' ? 'cubic B-spl.' : \
        w eq 'quintic_bspline' ? 'quintic B-spl.' : w
vname(v) = v eq 'voronoi' ? 'Voronoi' : '|Ω_H|/N'
# Decade-aligned ranges (computed before any range is set: stats applies the current ranges).
lo(x) = 10**floor(log10(x)); hi(x) = 10**ceil(log10(x))
xcol(c) = c == 1 ? "time_s" : "pairs"
set multiplot layout nrow,2 margins 95.0/W,1 - 195.0/W,60.0/H,1 - 75.0/H spacing 60.0/W,55.0/H \
    title 'Thesis Table '.table[1:1].'.'.table[3:3].': accuracy against cost, Case 2'
do for [k=1:nop] {
  osel = rows_named(f, sprintf('$c["operator"]=="%s" && $c["function"]=="case2"', word(ops, k)))
  do for [r=1:nw] {
    do for [c=1:2] {
      set autoscale xy
      stats osel using (column(xcol(c))) name 'SX' nooutput
      stats osel using (column("rel_error")) name 'SY' nooutput
      set xrange [lo(SX_min):hi(SX_max)]
      set yrange [lo(SY_min):hi(SY_max)]
      # Column heads on the first row; the row's operator and weight name its error axis.
      if (k == 1 && r == 1) { set title (c == 1 ? 'error against wall time' : 'error against pair interactions') } else { unset title }
      set xlabel (k < nop || r < nw ? '' : c == 1 ? 'wall time of the slice [s] (pass + Voronoi)' : 'neighbour pairs of the level')
      set ylabel (c == 1 ? sprintf("%s, %s:\nrelative ℓ^∞(Ω) error", word(ops, k), sh(word(ws, r))) : '')
      if (k == 1 && r == 1 && c == 2) { set key } else { unset key }
      plot for [i=1:nv*nh] \
           rows_named(f, sprintf('$c["operator"]=="%s" && $c["function"]=="case2" && $c["weight"]=="%s" && $c["volumes"]=="%s" && $c["h_reading"]=="%s"', \
                                 word(ops, k), word(ws, r), word(vols, V(i)), word(hs, R(i)))) \
           using (column(xcol(c))):(column("rel_error")) with linespoints lt i \
           title sprintf('%s, h %s', vname(word(vols, V(i))), word(hs, R(i)))
    }
  }
}
unset multiplot
