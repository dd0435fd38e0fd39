# Figure 4.8 (thesis §4.2): relative ℓ∞ error of the discrete Poisson problem against h,
# for the printed h = (2.6⁴·2^-10·Δx)^{1/4} (solid) and the reading (2.6⁴·2^-15·Δx)^{1/4}.
load 'figures/style.gp'
# Print size: 760 px wide (A4 text width 703 px), 14 px text, so nothing prints below 8 pt.
set terminal svg size 760,440 dynamic enhanced font 'Helvetica,14' background rgb 'white'
TRI_FONT = ',14'
set output out
set datafile columnheaders
# data_file, volumes_label (set by figures/store_reading.sh): the store file of one volume
# choice, named in the title.
f = exists('data_file') ? data_file : datadir.'/thesis_table4_4.tsv'
if (exists('volumes_label') && strlen(volumes_label) > 0) { set title 'volumes '.volumes_label }
set xlabel 'influence radius h'
set ylabel 'max_Ω|ũ − U| / max_Ω|ũ|  (ℓ^∞(Ω), relative)'
# The key in a strip of its own under the x label: never over the data or the published segments.
set bmargin at screen 0.27
set key at screen 0.5, screen 0.01 center bottom maxrows 4 samplen 1.5 width -4 box
w1 = 'quartic_polynomial'; w2 = 'piecewise_cubic_polynomial'; w3 = 'piecewise_quintic_polynomial'
sel(r, w) = rows_named(f, sprintf('$c["h_rule"]=="%s" && $c["weight"]=="%s"', r, w))
ANCHOR = sel('h10', w1); eval anchored_triangle(2, 'slope 2')
# The published rate of each (reading, weight), as a grey segment over the documents' level
# pair of its series (style.gp's published_segment; on the data where the rate agrees).
P = 'tables/published/thesis_table4_4_long.tsv'
pub(r, w) = published_rate(P, sprintf('$c["h_rule"]=="%s" && $c["weight"]=="%s"', r, w))
do for [r in "h10 h15"] {
  do for [w in w1.' '.w2.' '.w3] {
    ANCHOR = sel(r, w)
    p = pub(r, w)
    if (p == p) { eval published_segment(p) }
  }
}
stats f using (column("h")) nooutput
xlo = STATS_min * 0.8; xhi = STATS_max * 1.25; eval pow2_xtics
# Room below the data for the triangle and the published segments (a factor 4).
stats f using (column("rel_error")) name 'EY' nooutput
set yrange [EY_min / 4 : EY_max * 3]
H = 'using (column("h")):(column("rel_error")) with linespoints'
plot sel('h10', w1) @H lt 1 title 'quartic, h10 (printed)', \
     sel('h10', w2) @H lt 2 title 'pw. cubic, h10 (printed)', \
     sel('h10', w3) @H lt 3 title 'pw. quintic, h10 (printed)', \
     sel('h15', w1) @H lt 4 title 'quartic, h15', \
     sel('h15', w2) @H lt 5 title 'pw. cubic, h15', \
     sel('h15', w3) @H lt 6 title 'pw. quintic, h15', \
     NaN with lines lw 6 lc rgb '#bbbbbb' title 'published rate'
