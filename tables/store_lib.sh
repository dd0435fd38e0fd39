# Shell helpers shared by the scripts that read the result store (sourced, not run).

# heat_file STORE TABLE READING: the store file of one reading of a heat table (TABLE as
# 4_5; READING h10 or h15, then _cell for V_i = dx^2 and _exact for dt = dt0 exactly), and
# heat_label READING: its slice name in the rate tables (the reading's name; the older
# names h10_dtexact and h10_cellvol are mapped to it).  The one map from readings to files:
# h10 is the plain file, and the suffixes follow in the order _h15, _dtexact, _cellvol.
heat_readings="h10 h15 h10_cell h15_cell h10_exact h15_exact h10_cell_exact h15_cell_exact"
heat_file() {
  local r=$3 suffix=""
  case $r in h10_dtexact) r=h10_exact ;; h10_cellvol) r=h10_cell ;; esac
  case $r in h10|h15|h10_cell|h15_cell|h10_exact|h15_exact|h10_cell_exact|h15_cell_exact) ;;
    *) echo "heat_file: unknown reading '$3'" >&2; return 1 ;; esac
  case $r in h15*) suffix=_h15 ;; esac
  case $r in *_exact) suffix=${suffix}_dtexact ;; esac
  case $r in *_cell*) suffix=${suffix}_cellvol ;; esac
  echo "$1/thesis_table$2$suffix.tsv"
}
heat_label() { case $1 in h10_dtexact) echo h10_exact ;; h10_cellvol) echo h10_cell ;; *) echo "$1" ;; esac; }
