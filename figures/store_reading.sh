#!/usr/bin/env bash
# One of the thesis' Poisson and heat figures (4.8 for Table 4.4, 4.9-4.11 for Tables 4.5-4.7)
# drawn from the result store on one board: `identified` (the reading the set-up rule
# identified; the printed one where it decided none) or `printed`.  Which store file that is
# comes from FIGURE_FILES (gpm store-rates --figure-files, made in the same pass that judges
# the store and identifies the reading), read by column name.  OUT.data names the file
# plotted, for the report's provenance line (paper/tsv-tables.lua).
# usage: store_reading.sh SCRIPT.gp FIGURE BOARD STORE_DIR FIGURE_FILES OUT.svg
set -euo pipefail
usage="usage: store_reading.sh SCRIPT.gp FIGURE BOARD STORE_DIR FIGURE_FILES OUT.svg"
[ $# -eq 6 ] || { echo "$usage" >&2; exit 2; }
gp=$1 figure=$2 board=$3 store=$4 files=$5 out=$6
row=$(awk -F'\t' -v fig="$figure" -v board="$board" '/^#/ { next }
  !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["figure"] == fig && $c["board"] == board { print $c["reading"] "\t" $c["store_file"] }' "$files")
[ -n "$row" ] || { echo "store_reading: $files names no store file for figure '$figure' on board '$board'" >&2; exit 1; }
reading=${row%%$'\t'*}
f=$store/${row#*$'\t'}
[ -f "$f" ] || { echo "store_reading: no store file '$f' for reading '$reading' of $figure" >&2; exit 1; }
# The volumes in the title (Figure 4.8 draws both h rules of one volume choice).
case $reading in *_cell*) vol='V_i = Δx^2' ;; *) vol='V_i = |Ω_H|/N' ;; esac
mkdir -p "$(dirname "$out")"
gnuplot -e "datadir='$store'; data_file='$f'; volumes_label='$vol'; out='$out.tmp'" "$gp"
echo "$f" > "$out.data.tmp"
mv "$out.data.tmp" "$out.data"
mv "$out.tmp" "$out"
