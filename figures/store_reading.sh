#!/usr/bin/env bash
# One of the thesis' Poisson and heat figures (4.8 for Table 4.4, 4.9-4.11 for Tables 4.5-4.7)
# drawn from the result store in one reading of the set-up.  READING is a reading name (h10,
# h15_cell_exact, ...: tables/store_lib.sh's heat_readings) or `identified`, the reading the
# set-up rule identified (the `# identified = ` line of IDENT, setup_identification.tsv; h10,
# the reading as printed, where it decided none).  heat_file (tables/store_lib.sh) is the one
# map from a reading to its store file; Table 4.4 has no time step and keeps both h rules in
# one file per volume choice, so only the reading's volumes choose its file.  OUT.data names
# the file plotted, for the report's provenance line (paper/tsv-tables.lua).
# usage: store_reading.sh SCRIPT.gp TABLE(4_4|4_5|4_6|4_7) READING STORE_DIR IDENT OUT.svg
set -euo pipefail
[ $# -eq 6 ] || { echo "usage: store_reading.sh SCRIPT.gp TABLE READING STORE_DIR IDENT OUT.svg" >&2; exit 2; }
gp=$1 table=$2 reading=$3 store=$4 ident=$5 out=$6
source "$(dirname "$0")/../tables/store_lib.sh"
if [ "$reading" = identified ]; then
  reading=$(sed -n 's/^# identified = //p' "$ident")
  case $reading in ''|NA) reading=h10 ;; esac
fi
if [ "$table" = 4_4 ]; then
  case $reading in *_cell*) f=$store/thesis_table4_4_cellvol.tsv vol='V_i = Δx^2' ;;
                   *) f=$store/thesis_table4_4.tsv vol='V_i = |Ω_H|/N' ;; esac
  heat_file "$store" 4_5 "$reading" > /dev/null  # the same check of the reading's name
else
  f=$(heat_file "$store" "$table" "$reading") vol=''
fi
[ -f "$f" ] || { echo "store_reading: no store file '$f' for reading '$reading' of Table ${table/_/.}" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
gnuplot -e "datadir='$store'; data_file='$f'; volumes_label='$vol'; out='$out.tmp'" "$gp"
echo "$f" > "$out.data.tmp"
mv "$out.data.tmp" "$out.data"
mv "$out.tmp" "$out"
