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
