#!/usr/bin/env bash
# One of the thesis' Poisson and heat figures (4.8 for Table 4.4, 4.9-4.11 for Tables 4.5-4.7)
# drawn from the result store in one reading of the set-up.  READING is a reading name (h10,
# h15_cell_exact, ...: `gpm study --readings`) or `identified`, the reading the set-up rule
# identified (the `# identified = ` line of IDENT, setup_identification.tsv; h10, the reading
# as printed, where it decided none).  The study registry maps a reading to its store file
# (`gpm study --reading-file STUDY READING`; Table 4.4 has no time step and keeps both h rules
# in one file per volume choice).  OUT.data names the file plotted, for the report's
# provenance line (paper/tsv-tables.lua).
# usage: store_reading.sh GPM SCRIPT.gp STUDY READING STORE_DIR IDENT OUT.svg
set -euo pipefail
[ $# -eq 7 ] || { echo "usage: store_reading.sh GPM SCRIPT.gp STUDY READING STORE_DIR IDENT OUT.svg" >&2; exit 2; }
gpm=$1 gp=$2 study=$3 reading=$4 store=$5 ident=$6 out=$7
if [ "$reading" = identified ]; then
  reading=$(sed -n 's/^# identified = //p' "$ident")
  case $reading in ''|NA) reading=h10 ;; esac
fi
f=$store/$("$gpm" study --reading-file "$study" "$reading").tsv
[ -f "$f" ] || { echo "store_reading: no store file '$f' for reading '$reading' of $study" >&2; exit 1; }
# The volumes in the title (Figure 4.8 draws both h rules of one volume choice).
case $reading in *_cell*) vol='V_i = Δx^2' ;; *) vol='V_i = |Ω_H|/N' ;; esac
mkdir -p "$(dirname "$out")"
gnuplot -e "datadir='$store'; data_file='$f'; volumes_label='$vol'; out='$out.tmp'" "$gp"
echo "$f" > "$out.data.tmp"
mv "$out.data.tmp" "$out.data"
mv "$out.tmp" "$out"
