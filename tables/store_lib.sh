# Shell helpers shared by the scripts that read the result store (sourced, not run).

# finite FILE: the rows of the heat series (weight, theta) that never blew up, header kept —
# the same rows thesis_heat's --rates-input file holds.
finite() {
  awk -F'\t' '
    FNR==1 && NR!=FNR { pass=2 }
    /^#/ { if (pass==2) print; next }
    !seen[pass]++ { for (i=1;i<=NF;i++) c[$i]=i; if (pass==2) print; next }
    pass!=2 { if ($c["blew_up"]=="yes") bad[$1 "|" $2]=1; next }
    !(($1 "|" $2) in bad)' "$1" "$1"
}

# heat_file STORE TABLE VARIANT: the store file of one variant of a heat table (TABLE as
# 4_5; VARIANT h10, h15, h10_dtexact, h10_cellvol), and heat_label VARIANT: its slice name in
# the rate tables.  The one list of the heat variants' files.
heat_variants="h10 h15 h10_dtexact h10_cellvol"
heat_file() {
  case $3 in
    h10) echo "$1/thesis_table$2.tsv" ;;
    h15) echo "$1/thesis_table$2_h15.tsv" ;;
    h10_dtexact) echo "$1/thesis_table$2_dtexact.tsv" ;;
    h10_cellvol) echo "$1/thesis_table$2_cellvol.tsv" ;;
    *) echo "heat_file: unknown variant '$3'" >&2; return 1 ;;
  esac
}
heat_label() { if [ "$1" = h10_dtexact ]; then echo "h10_dtexact (dt = dt0 exactly)"; else echo "$1"; fi; }
