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

  # --- Table 4.4: where the error sits, seeds, plain grid. --------------------------------------
  d=$store/thesis_poisson_diagnostic.tsv
  if [ -f "$d" ]; then
    # The operator's smoothing error eps(kh) at each radius (gpm smoothing: no particles).
    hs=$(awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } { print $c["h"] }' "$d" | sort -u | paste -sd,)
    "$build/gpm" smoothing --weight quartic_polynomial --h "$hs" | awk -F'\t' '!/^#/ && $1 != "h"' > "$tmp/eps.tsv"
    awk -F'\t' 'NR==FNR { eps[$1]=$3; next }

      /^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
      $c["weight"] != "quartic_polynomial" { next }
      { r=$c["h_rule"]; l=$c["level"]; v=$c["variant"]; e=$c["rel_error"]+0; dd=$c["max_distance_over_h"]+0
        if (v=="plain") { plain[r,l]=e; hasplain[r,l]=1 } else { k=r SUBSEP l; if (!(k in lo) || e<lo[k]) lo[k]=e; if (!(k in hi) || e>hi[k]) hi[k]=e }
        k2=r SUBSEP l; if (!(k2 in dmin) || dd<dmin[k2]) dmin[k2]=dd; seen[r,l]=1; hov[r,l]=$c["h_over_H"]
        err[r,l,v]=e; hh[r,l]=$c["h"]; ep[r,l]=eps[$c["h"]]; vars[v]=1 }
      END {
        for (ri=1; ri<=2; ri++) { r = ri==1 ? "h10" : "h15"; ev=""
          for (l=7; l<=9; l++) if ((r,l) in seen)
            ev = ev sprintf(" 2^-%d (h/H %.2f): seeds error %.3g to %.3g, plain grid %s, operator smoothing error eps %.3g, maximum at least %.2f h from the boundary;",
                            l, hov[r,l], lo[r,l], hi[r,l], ((r,l) in hasplain) ? sprintf("%.3g", plain[r,l]) : "not yet computed", ep[r,l], dmin[r,l])
          # Two-level rates 2^-8 -> 2^-9 of each particle set that has both levels.
          rt=""
          for (v in vars) if (((r,8,v) in err) && ((r,9,v) in err))
            rt = rt sprintf(" %s %.2f", v, log(err[r,8,v]/err[r,9,v]) / log(hh[r,8]/hh[r,9]))
          if (rt != "") ev = ev " rates 2^-8/2^-9:" rt sprintf(", of eps alone %.2f;", log(ep[r,8]/ep[r,9]) / log(hh[r,8]/hh[r,9]))
          printf "Table 4.4, quartic weight, %s: where the error sits\t%s\t%s\n", r, ev,
            "the smallest distance of the maximum from the boundary is in the evidence column: a value above 1 puts it outside the boundary layer of width h; eps is the part of the error the operator makes without particles" } }' "$tmp/eps.tsv" "$d"
  else
    printf 'Table 4.4: where the error sits\tnot yet in the store\topen\n'
  fi

  # --- The gradient norm (decided by the documents' definitions). ----------------------------
  printf 'Gradient error norm\timoto Sec. 1 defines |x| as the Euclidean norm; the thesis writes [l-inf(Omega)]^2 for vector fields; test "gradient error: Euclidean norm, brute force reference" checks the fused pass against a brute-force Euclidean evaluation and that the component-wise value differs\tEuclidean length of the error vector, maximum over particles in Omega (all gradient data since this change)\n'
} > "$out.tmp"
mv "$out.tmp" "$out"
