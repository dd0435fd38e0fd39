# Atlas of a thesis truncation table (4.1-4.3), Case 2 (sin 2π(x+y)): relative error
# against wall time (left) and neighbour pairs (right), one row per operator.  Time = the
# fused pass of the (h reading, volumes, level) slice — shared by every weight of the slice,
# not apportioned — plus the Voronoi volumes where they are used.  Point type = weight,
# dash pattern = volume choice and h reading.  Set `table` (e.g. '4_1') before loading.
# Columns are addressed by name (rel_error, time_s, pairs, operator, function, volumes,
# h_reading, weight of atlas_thesis_table<t>.tsv).
load 'figures/style.gp'
f = datadir.'/atlas_thesis_table'.table.'.tsv'
uniq(c) = system(sprintf("awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } $c[\"function\"]==\"case2\" { print $c[\"%s\"] }' '%s' | sort -u | tr '\n' ' '", c, f))
ops = uniq('operator'); ws = uniq('weight'); vols = uniq('volumes'); hs = uniq('h_reading')
nrow = words(ops)
nw = words(ws); nv = words(vols); nh = words(hs)
# One flat index over (weight, volumes, h reading): nested plot-for loops are kept shallow.
J(i) = i / (nv * nh) + 1; V(i) = (i / nh) % nv + 1; R(i) = i % nh + 1
D(i) = (V(i) - 1) * nh + R(i)  # dash pattern (a bare "dt (" would read as a custom pattern)
set terminal svg size 1050,(nrow * 400 + 60) dynamic enhanced font 'Helvetica,11' background rgb 'white'
set output out
set datafile columnheaders
set format x '10^{%T}'
set format y '10^{%T}'
set ylabel 'relative ℓ^∞(Ω) error, Case 2'
set key outside right font ',9' samplen 3 noenhanced
sh(w) = w eq 'piecewise_cubic_polynomial' ? 'pw. cubic' : w eq 'piecewise_quintic_polynomial' ? 'pw. quintic' : \
        w eq 'quartic_polynomial' ? 'quartic' : w eq 'quadratic_spike' ? 'quadr. spike' : \
        w eq 'cubic_spike' ? 'cubic spike' : w eq 'cubic_bspline' ? 'cubic B-spl.' : \
        w eq 'quintic_bspline' ? 'quintic B-spl.' : w
vname(v) = v eq 'voronoi' ? 'Voronoi' : '|Ω_H|/N'
set multiplot layout nrow,2 title 'Thesis Table '.table[1:1].'.'.table[3:3].': accuracy against cost'
do for [k=1:nrow] {
  do for [c=1:2] {
    set title sprintf('%s: error against %s', word(ops, k), c == 1 ? 'wall time' : 'pair interactions')
    set xlabel (c == 1 ? 'wall time of the slice [s] (pass + Voronoi)' : 'neighbour pairs of the level')
    if (c == 1) { unset key } else { set key }
    plot for [i=0:nw*nv*nh-1] \
         rows_named(f, sprintf('$c["operator"]=="%s" && $c["function"]=="case2" && $c["weight"]=="%s" && $c["volumes"]=="%s" && $c["h_reading"]=="%s"', \
                               word(ops, k), word(ws, J(i)), word(vols, V(i)), word(hs, R(i)))) \
         using (column(c == 1 ? "time_s" : "pairs")):(column("rel_error")) with linespoints lt J(i) dt D(i) \
         title sprintf('%s, %s, h %s', sh(word(ws, J(i))), vname(word(vols, V(i))), word(hs, R(i)))
  }
}
unset multiplot
