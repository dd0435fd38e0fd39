#!/usr/bin/env bash
# The open set-up questions of the documents and what the stored paper-profile data say about
# each: one row per question, every number read from a data file of the result store, none
# typed.  A question whose runs are not yet in the store says so.
#
# usage: decisions.sh BUILD_DIR STORE_DIR OUT
set -euo pipefail
build=$1 store=$2 out=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pub=tables/published
source "$(dirname "$0")/store_lib.sh"  # finite

# rates FILE LEVELS KEY: two-level rates of FILE's finite heat rows at LEVELS (rate_table)
rates() {
  finite "$1" > "$tmp/finite.tsv"
  "$build/rate_table" --data "$tmp/finite.tsv" --published "$pub/thesis_table4_7_long.tsv" \
    --key weight,theta --levels "$2" --out "$tmp/r.tsv" >/dev/null
}
# span COLUMN FILTER-COLUMN VALUE FILE: "min-max" of COLUMN over the rows whose FILTER-COLUMN is VALUE
span() {
  awk -F'\t' -v col="$1" -v fc="$2" -v fv="$3" '
    /^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
    $c[fc]==fv && $c["status"]!="not-computed" { v=$c[col]+0; if (n++==0 || v<lo) lo=v; if (n==1 || v>hi) hi=v }
    END { if (n) printf "%.2f to %.2f", lo, hi; else printf "none" }' "$4"
}

{
  echo "# program = tables/decisions.sh"
  echo "# store = $store"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'question\tevidence\tdecision\n'

  # --- Table 4.7: the time step. ------------------------------------------------------------
  # Per pair of levels, the theta = 1 and theta = 1/2 rates under both readings, and which
  # reading lies closer to the published rates (mean |reproduced - published| over weights).
  fit=$store/thesis_table4_7.tsv ex=$store/thesis_table4_7_dtexact.tsv
  if [ -f "$fit" ] && [ -f "$ex" ]; then
    ev="" verdict=""
    for lv in 7,8 8,9; do
      rates "$fit" $lv; cp "$tmp/r.tsv" "$tmp/fit.tsv"
      rates "$ex" $lv; cp "$tmp/r.tsv" "$tmp/ex.tsv"
      f1=$(span reproduced theta 1 "$tmp/fit.tsv"); e1=$(span reproduced theta 1 "$tmp/ex.tsv")
      if [ "$f1" = none ] || [ "$e1" = none ]; then
        ev="$ev levels ${lv/,/\/}: not yet computed under both readings."
        continue
      fi
      f5=$(span reproduced theta 0.5 "$tmp/fit.tsv"); e5=$(span reproduced theta 0.5 "$tmp/ex.tsv")
      p1=$(span published theta 1 "$tmp/fit.tsv"); p5=$(span published theta 0.5 "$tmp/fit.tsv")
      ev="$ev levels ${lv/,/\/}: theta=1 rates $f1 with dt = T/K, $e1 with dt = dt0 (published $p1); theta=1/2 $f5 and $e5 (published $p5)."
      verdict=$(awk -F'\t' -v lv="${lv/,/\/}" '/^#/ { next } !h[FILENAME]++ { for (i=1;i<=NF;i++) c[FILENAME, $i]=i; next }
        { d = $c[FILENAME, "reproduced"] - $c[FILENAME, "published"]; s[FILENAME] += d < 0 ? -d : d; n[FILENAME]++ }
        END { a = s[ARGV[1]] / n[ARGV[1]]; b = s[ARGV[2]] / n[ARGV[2]]
              printf "at levels %s the closer reading is %s (mean |rate - published| %.2f against %.2f)", lv,
                     (b < a ? "dt = dt0" : "dt = T/K"), (b < a ? b : a), (b < a ? a : b) }' "$tmp/fit.tsv" "$tmp/ex.tsv")
    done
    Kf=$(awk -F'\t' '/^#/{next} !h++{for(i=1;i<=NF;i++)c[$i]=i;next} {k[$c["level"]]=$c["K"]} END{for(l=5;l<=9;l++) if(l in k) printf "%s2^-%d: %s", (n++?", ":""), l, k[l]}' "$fit")
    printf 'Table 4.7 (dt = 0.5h, T = 0.1): dt = T/K with K = ceil(T/dt0) (the thesis defines dt = T/K), or dt = dt0 as prescribed\t%s Steps K under dt = T/K: %s.\tboth readings kept; %s\n' "$ev" "$Kf" "${verdict:-no level pair computed under both}"
  else
    printf 'Table 4.7 (dt = 0.5h, T = 0.1): dt = T/K or dt = dt0\tnot yet in the store\topen\n'
  fi

  # --- Table 4.4: what sets the error. ------------------------------------------------------
  # Per reading of h: the error over the consistency |tau_predicted| = |(V/dx^2)(1 - eps) - 1|
  # at every level and particle set (a constant ratio means the error is that consistency
  # error, carried through the solve), and the 2^-8/2^-9 rates of each particle set with the
  # volumes of (A.10) and with V_i = dx^2, against the published ones.
  d=$store/thesis_poisson_diagnostic.tsv
  if [ -f "$d" ] && grep -q tau_predicted "$d"; then
    awk -F'\t' '
      function abs(x) { return x < 0 ? -x : x }
      FILENAME == ARGV[1] { if (/^#/ || !hp++) next; pub[$1, $2] = $3; next }
      /^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
      { r=$c["h_rule"]; w=$c["weight"]; l=$c["level"]; v=$c["variant"]
        e=$c["rel_error"]+0; q=e/abs($c["tau_predicted"]); rules[r]=1; W[w]=1; V[v]=1
        g = r SUBSEP (v ~ /^plain/ ? "plain grid" : "jittered grids")
        if (!(g in qlo) || q<qlo[g]) qlo[g]=q; if (!(g in qhi) || q>qhi[g]) qhi[g]=q
        err[r,w,l,v]=e; hh[r,l]=$c["h"]; mm[l, v ~ /_cell$/]=$c["volume_mismatch"] }
      END {
        for (ri=1; ri<=2; ri++) { r = ri==1 ? "h10" : "h15"; if (!(r in rules)) continue
          ev = sprintf("error / |(V/dx^2)(1 - eps) - 1| over the weights and levels 2^-7..2^-9: plain grid %.2f to %.2f, jittered grids %.2f to %.2f; volume mismatch V/dx^2 - 1 of (A.10): %+.2f%% (2^-7), %+.2f%% (2^-8), %+.2f%% (2^-9).",
                       qlo[r, "plain grid"], qhi[r, "plain grid"], qlo[r, "jittered grids"], qhi[r, "jittered grids"], 100*mm[7,0], 100*mm[8,0], 100*mm[9,0])
          for (w in W) { line = ""
            split("seed1 plain seed1_cell plain_cell", vs, " ")
            for (j=1; j<=4; j++) { v=vs[j]
              if (((r,w,8,v) in err) && ((r,w,9,v) in err))
                line = line sprintf(" %s %.2f", v, log(err[r,w,8,v]/err[r,w,9,v]) / log(hh[r,8]/hh[r,9])) }
            if (line != "") ev = ev sprintf(" %s, rates 2^-8/2^-9:%s (published %s).", w, line, pub[r, w]) }
          printf "Table 4.4, %s: the volumes (A.10) on the grid G_dx\t%s\t%s\n", r, ev,
            "the error is the operator consistency error (V/dx^2)(1 - eps) - 1 carried through the solve; with (A.10) on G_dx the volume mismatch changes sign between 2^-8 and 2^-9 and sets the rates; with V_i = dx^2 the rates are those of eps alone (rows *_cell). Kept: (A.10) as the thesis prints it; the published rates match V_i = dx^2" } }' \
      "$pub/thesis_table4_4_long.tsv" "$d"
  else
    printf 'Table 4.4: the volumes of (A.10)\tnot yet in the store\topen\n'
  fi

  # --- The gradient norm (decided by the documents' definitions). ----------------------------
  printf 'Gradient error norm\timoto Sec. 1 defines |x| as the Euclidean norm; the thesis writes [l-inf(Omega)]^2 for vector fields; test "gradient error: Euclidean norm, brute force reference" checks the fused pass against a brute-force Euclidean evaluation and that the component-wise value differs\tEuclidean length of the error vector, maximum over particles in Omega (all gradient data since this change)\n'
} > "$out.tmp"
mv "$out.tmp" "$out"
