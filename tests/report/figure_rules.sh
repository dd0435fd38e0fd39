#!/bin/bash
# The figure rules that can be read off the SVG files gnuplot writes, checked per panel:
#   * greyscale: no two titled series of one panel share both their dash pattern and their
#     point symbol (in grey, colour is all that would tell them apart);
#   * at most MAX titled series per panel (reference overlays - the published rates, the
#     slope triangles - do not count);
#   * no titled series whose line joins exactly two points (two points always make a straight
#     line: a convergence plot needs a third to show a trend; two points without a line pass).
# Geometric diagrams, whose elements differ by shape (cells, discs, edges), are listed in
# figure_rules_exempt.tsv with the reason.  One line per violation; exit 1 if any.
#   bash figure_rules.sh FIGURE_DIR [MAX]      (default MAX = 6)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
dir=${1:?usage: figure_rules.sh FIGURE_DIR [MAX]}
max=${2:-6}
here=$(cd "$(dirname "$0")" && pwd)
shopt -s nullglob
files=("$dir"/*.svg)
[ ${#files[@]} -gt 0 ] || { echo "figure_rules: no SVG files in '$dir'" >&2; exit 2; }
bad=0 n=0
for f in "${files[@]}"; do
  name=$(basename "$f" .svg)
  if awk -F'\t' -v n="$name" '$1 == n { found = 1 } END { exit !found }' "$here/figure_rules_exempt.tsv"; then
    continue
  fi
  n=$((n + 1))
  out=$(awk -v file="$name" -v max="$max" '
    # A new panel starts where gnuplot numbers its plots from 1 again.
    function flush(   i, j, cnt) {
      if (ns == 0) return
      cnt = 0
      for (i = 1; i <= ns; i++) {
        if (title[i] == "" || title[i] ~ /^(published|slope)/) continue
        cnt++
        # With the key drawn, the group also holds the sample symbol of the legend beside its text.
        if (haspath[i] && npt[i] - (keytext[i] && npt[i] > 0) == 2)
          printf "%s panel %d: \"%s\" is drawn through two points only\n", file, panel, title[i]
        for (j = 1; j < i; j++)
          if (title[j] != "" && title[j] !~ /^(published|slope)/ && style[i] == style[j])
            printf "%s panel %d: \"%s\" and \"%s\" differ only in colour (%s)\n", file, panel, title[j], title[i], style[i]
      }
      if (cnt > max) printf "%s panel %d: %d series (at most %d)\n", file, panel, cnt, max
      ns = 0
    }
    match($0, /<g id="gnuplot_plot_[0-9]+/) {
      k = substr($0, RSTART + 20, RLENGTH - 20) + 0
      if (k == 1) { flush(); panel++ }
      cur = ++ns; title[cur] = ""; dash[cur] = "solid"; pt[cur] = "none"; got_d[cur] = got_p[cur] = npt[cur] = keytext[cur] = haspath[cur] = 0
      depth = 0 }
    # The group of a plot ends where its <g> closes; what follows (axes, labels) is not its own.
    cur { depth += gsub(/<g[ >]/, "&") - gsub(/<\/g>/, "&"); if (depth < 0) depth = 0 }
    # gnuplot names an untitled plot by its id: not a series of the legend.
    cur && /<title>/ { t = $0; sub(/.*<title>/, "", t); sub(/<\/title>.*/, "", t); title[cur] = t ~ /^gnuplot_plot_/ ? "" : t }
    cur && !got_d[cur] && match($0, /stroke-dasharray=.[^ \/>'"'"']*/) { dash[cur] = substr($0, RSTART + 18, RLENGTH - 18); got_d[cur] = 1 }
    cur && !got_p[cur] && match($0, /#gpPt[0-9]+/) { pt[cur] = substr($0, RSTART + 1, RLENGTH - 1); got_p[cur] = 1 }
    # Each data point of a series with symbols is one <use> of a point glyph in its group.
    cur { npt[cur] += gsub(/<use xlink:href=.#gpPt/, "&") }
    cur && /<text>/ { keytext[cur] = 1 }
    cur && /<path/ { haspath[cur] = 1 }
    cur { style[cur] = "line " dash[cur] ", point " pt[cur] }
    cur && depth == 0 { cur = 0 }
    END { flush() }' "$f")
  if [ -n "$out" ]; then echo "$out"; bad=$((bad + $(wc -l <<<"$out"))); fi
done
echo "figure_rules: $n figures checked, $bad violations"
[ "$bad" -eq 0 ]
