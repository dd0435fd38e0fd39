#!/usr/bin/env bash
# Page one of the report: one verdict per item of the three documents (tables/items.tsv),
# each with the number that decides it, computed from the data files.  The table is compact:
# a figure drawn from a table's rows ("as T") shares that table's row, and neighbouring
# illustrations of one document share one row.  The rules:
#   rates T    the paper-scale verdicts of T's published rates (store_score.tsv, the counted
#              setting): reproduced when every rate agrees, is inside the seed band or
#              reproduces non-convergence; partial when some do; not reproduced when none do;
#              not yet computed when the store lacks the table;
#   as T       a figure of T's errors: merged into T's row, since it is drawn from the same rows;
#   cor71      Corollary 7.1: printed coefficients that hold (koba_sato_cor71.tsv, holds);
#   bounds     Theorems 1.3–1.6: cases where a bound falls below the measured error
#              (koba_sato_bounds_summary.tsv, violations);
#   covering   Imoto's covering bound: (level, seed) pairs where it holds (imoto_regularity_cover.tsv);
#   fig3       Imoto Fig. 3: r_N of the uniform against the non-uniform distribution;
#   count      N of the distribution at Δx = 2⁻⁵ against the printed 1521 (core_voronoi.tsv);
#   weights W  the plotted weights: printed formulas that fail normalization
#              (core_weights_errata.tsv) and the norm of the corrected ones (core_weights.tsv);
#   drawn      an illustration drawn from the definitions: reproduced qualitatively.
# A rate table's evidence gives the counts of both boards (as identified, which decides the
# verdict, and as printed), naming only the verdicts that occur.
# usage: verdicts.sh ITEMS STORE_SCORE DATA_DIR OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
items=$1 score=$2 data=$3 out=$4
{
  echo "# program = tables/verdicts.sh"
  echo "# items = $items"
  echo "# score = $score (paper scale, the result store)"
  echo "# data = $data"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'document\titem\tshows\tverdict\tevidence\tsection\n'
  awk -F'\t' -v score="$score" -v data="$data" '
    function load(file, T,   line, f, c, i, k, n) {  # the rows of a TSV file as T[row, column name]
      delete T; n = 0; close(file)
      while ((getline line < file) > 0) { if (line ~ /^#/) continue
        k = split(line, f, "\t")
        if (!("h" in c)) { for (i = 1; i <= k; i++) c[i] = f[i]; c["h"] = 1; continue }
        n++; for (i = 1; i <= k; i++) T[n, c[i]] = f[i] }
      close(file); return n }
    # "3 agree, 9 non-convergence, 11 unexplained of 27": the verdicts of row i of the score
    # that occur, in the order of the paper-scale chapter.
    function counts(i,   k, out) {
      out = ""
      for (k = 1; k <= ncat; k++) if (S[i, cat[k]] + 0 > 0) out = out (out == "" ? "" : ", ") S[i, cat[k]] " " word[k]
      return (out == "" ? "none" : out) " of " S[i, "rates"] }
    function rates(t,   v, ev) {
      ev = (t in prow ? (t in crow && crow[t] == prow[t] ? "both boards: " counts(crow[t]) : \
              (t in crow ? "identified: " counts(crow[t]) : "identified reading not stored") "; printed: " counts(prow[t])) : \
            "no rows in the store")
      if (!(t in total)) return "not yet computed\t" ev
      if (nc[t] == total[t]) return "not yet computed\t" ev
      v = (good[t] == total[t]) ? "reproduced" : (good[t] > 0 ? "partial" : (cr[t] > 0 && cr[t] + nc[t] == total[t] ? "not reproduced (reason checked)" : "not reproduced"))
      return v "\t" ev }
    BEGIN {
      ncat = split("agrees non_convergence in_seed_band fingerprint checked_reason explained_ours unexplained indeterminate undefined not_computed", cat, " ")
      split("agree|non-convergence|in seed band|fingerprint|checked reason|ours explained|unexplained|indeterminate|undefined|not computed", word, "|")
      n = load(score, S)
      for (i = 1; i <= n; i++) {
        t = S[i, "table"]; if (t == "total") continue
        if (S[i, "printed"] == "yes") prow[t] = i
        if (S[i, "counted"] != "yes") continue
        crow[t] = i
        total[t] = S[i, "rates"]; ag[t] = S[i, "agrees"]; ncv[t] = S[i, "non_convergence"]
        sb[t] = S[i, "in_seed_band"]; cr[t] = S[i, "checked_reason"]; un[t] = S[i, "unexplained"]; nc[t] = S[i, "not_computed"]
        fp[t] = S[i, "fingerprint"]
        good[t] = ag[t] + ncv[t] + sb[t] } }
    /^#/ || $1 == "document" { next }
    { split($4, r, " "); kind = r[1]; arg = r[2]; res = "" }
    kind == "rates" { res = rates(arg) }
    kind == "as" { res = "as\t" arg }
    kind == "cor71" { n = load(data "/koba_sato_cor71.tsv", T); h = 0
      for (i = 1; i <= n; i++) h += (T[i, "holds"] == 1)
      res = (n == 0 ? "not yet computed\t-" : ((h == n ? "reproduced" : "published value wrong") "\t" sprintf("%d of %d printed coefficients hold", h, n))) }
    kind == "bounds" { rows = load(data "/koba_sato_bounds_summary.tsv", T); n = v = 0; m = 1e300
      for (i = 1; i <= rows; i++) { n += T[i, "cases"]; v += T[i, "violations"]; if (T[i, "min_ratio"] + 0 < m) m = T[i, "min_ratio"] + 0 }
      res = (n == 0 ? "not yet computed\t-" : ((v == 0 ? "reproduced" : "published value wrong") "\t" sprintf("bound below the measured error in %d of %d cases (smallest bound/error %.3g)", v, n, m))) }
    kind == "covering" { n = load(data "/imoto_regularity_cover.tsv", T); h = 0
      for (i = 1; i <= n; i++) h += T[i, "claim_holds"]
      res = (n == 0 ? "not yet computed\t-" : ((h == n ? "reproduced" : "published value wrong") "\t" sprintf("the bound holds on %d of %d (level, seed) distributions", h, n))) }
    kind == "fig3" { n = load(data "/imoto_figs_fig3_discs.tsv", T); delete rn
      for (i = 1; i <= n; i++) rn[T[i, "distribution"]] = T[i, "r_N"]
      res = (!("uniform" in rn) ? "not yet computed\t-" : ((rn["uniform"] < rn["non-uniform"] ? "reproduced" : "not reproduced") "\t" sprintf("r_N = %.4g (uniform) against %.4g (non-uniform), same N", rn["uniform"], rn["non-uniform"]))) }
    kind == "count" { n = load(data "/core_voronoi.tsv", T); N = ""
      for (i = 1; i <= n; i++) if (T[i, "level"] == 5 && T[i, "distribution"] == "jittered") N = T[i, "N"]
      res = (N == "" ? "not yet computed\t-" : ((N == 1521 ? "reproduced" : "not reproduced") "\t" sprintf("N = %s at Δx = 2⁻⁵ (printed: 1521)", N))) }
    kind == "weights" { nw = split(arg, w, ","); wrong = ""; ok = ""
      n = load(data "/core_weights_errata.tsv", T); delete bad
      for (i = 1; i <= n; i++) bad[T[i, "name"]] = T[i, "printed_norm"]
      n = load(data "/core_weights.tsv", T); delete nrm
      for (i = 1; i <= n; i++) nrm[T[i, "name"]] = T[i, "norm"]
      for (i = 1; i <= nw; i++) {
        nm = w[i]; gsub(/_/, " ", nm)  # "cubic bspline": a name a table cell can wrap between words
        if (w[i] in bad) wrong = wrong sprintf("%s%s %.4g", wrong == "" ? "" : ", ", nm, bad[w[i]])
        if (w[i] in nrm) ok = ok sprintf("%s%s %.6g", ok == "" ? "" : ", ", nm, nrm[w[i]]) }
      res = (ok == "" ? "not yet computed\t-" : ((wrong != "" ? "published value wrong" : "reproduced") "\t" (wrong != "" ? "norm as printed: " wrong "; " : "") "norm of the plotted (corrected) weights: " ok)) }
    kind == "drawn" { res = "reproduced qualitatively\tillustrations drawn from the same definitions (no number to compare)" }
    res == "" { res = "not yet computed\tunknown rule " $4 }
    # Rows in the order of items.tsv; an "as T" figure joins the row of T, and an illustration
    # joins the row before it when that row is an illustration of the same document.
    { split(res, q, "\t")
      if (q[1] == "as") {
        if (q[2] in tab) item[tab[q[2]]] = item[tab[q[2]]] ", " $2
        else fig[q[2]] = fig[q[2]] ", " $2
        next }
      if (kind == "drawn" && nrow > 0 && rule[nrow] == "drawn" && doc[nrow] == $1) {
        item[nrow] = item[nrow] ", " $2; shows[nrow] = shows[nrow] "; " $3; next }
      nrow++; doc[nrow] = $1; item[nrow] = $2; shows[nrow] = $3; verdict[nrow] = q[1]; evidence[nrow] = q[2]; sect[nrow] = $5; rule[nrow] = kind
      if (kind == "rates") { tab[arg] = nrow; item[nrow] = item[nrow] fig[arg] } }
    END {
      for (t in fig) if (!(t in tab)) { print "verdicts: a figure is drawn from " t ", which items.tsv gives no rates row" > "/dev/stderr"; exit 1 }
      for (i = 1; i <= nrow; i++) printf "%s\t%s\t%s\t%s\t%s\t%s\n", doc[i], item[i], shows[i], verdict[i], evidence[i], sect[i] }' "$items"
} > "$out.tmp"
mv "$out.tmp" "$out"
