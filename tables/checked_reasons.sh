#!/usr/bin/env bash
# Reasons for paper-scale rates that differ from the published ones, each CHECKED against the
# stored data: one row per published rate (table, slice, key), with the diagnostic's numbers
# (read from the store, none typed) and `check` = pass or fail.  gpm store-rates accepts a
# reason for a differing rate only when its row here passes; otherwise the rate stays
# "differs, unexplained".
#
# Table 4.4 (thesis §4.2): the volume mismatch of (A.10).  thesis_poisson_diagnostic records,
# per reading of h, weight, level and particle set, the error and the operator's consistency
# on u predicted from the smoothing error and the volume mismatch alone,
#   tau_predicted = (V_i/dx^2)(1 - eps(kh)) - 1,
# and the same problem with V_i = dx^2 (variant seed1_cell).  The reason holds for a row when
#   (a) the rate predicted by |tau_predicted| (2^-8 -> 2^-9) is within TOL of the reproduced
#       rate (the mechanism accounts for the number), and
#   (b) the rate with V_i = dx^2 on the same particles is within TOL of the published rate
#       (removing the cause restores the documents' number).
#
# Tables 4.5–4.7 (thesis §4.3): the one-mode error.  thesis_heat_mode_model predicts each
# stored error from the exact solution's single Fourier mode: the θ-step's amplification at
# the discrete decay rate μ(1 + δ)(1 − ε), δ the volume mismatch of (A.10) (it changes sign
# between 2^-8 and 2^-9), ε the smoothing error.  The reason holds for a (weight, θ) when
#   (a) measured/predicted lies in [0.9, 1.1] at both rate levels and the predicted rate is
#       within TOL of the reproduced one (the model accounts for the number), and
#   (b) the rate measured with V_i = dx^2 (the table's _cellvol or _dtexact_cellvol file,
#       whichever ran the same Δt rule) is within
#       TOL of the published rate (removing the mismatch restores the documents' number).
#
# Table 4.3 (thesis §4.1.2), gradient of Case 2 (sin 2π(x+y)): the operator's own smoothing
# error.  `gpm smoothing --operator grad` gives ε_∇(|k|h), the relative error of the continuous
# gradient on the mode (smoothing.hpp).  The reason holds for a weight when
#   (a) the stored error equals ε_∇ within 1 % at both rate levels (no particle part is left:
#       the reproduced rate is the operator's own), and
#   (b) the published rate lies more than TOL from the rate of ε_∇ over the same two h — a
#       rate the operator cannot give at these h, whatever the particles.
#
# usage: checked_reasons.sh STORE_DIR OUT BUILD_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
store=$1 out=$2 build=${3:?usage: checked_reasons.sh STORE_DIR OUT BUILD_DIR}
source "$(dirname "$0")/store_lib.sh"  # heat_file, heat_label
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
# smoothing_rows STORE_FILE PUBLISHED READING OPERATOR FUNCTION GPM_OPERATOR: for the Voronoi rows
# of one reading, operator (interp, grad, …) and function at the document's two rate levels,
# "weight level h rel_error smoothing_part" (gpm smoothing --operator GPM_OPERATOR at that h),
# sorted by weight and level.
smoothing_rows() {
  local lv
  lv=$(awk '/^# rate_levels = / { print substr($0, 17); exit }' "$2")
  awk -F'\t' -v r="$3" -v op="$4" -v fn="$5" -v lv="$lv" 'BEGIN { split(lv, L, ",") } /^#/ { next }
    !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["h_reading"] == r && $c["volumes"] == "voronoi" && $c["operator"] == op &&
    $c["function"] == fn && ($c["level"] == L[1] || $c["level"] == L[2]) {
      print $c["weight"] "\t" $c["level"] "\t" $c["h"] "\t" $c["rel_error"] }' "$1" |
    sort -k1,1 -k2,2n |
    while IFS=$'\t' read -r w l h e; do
      printf '%s\t%s\t%s\t%s\t%s\n' "$w" "$l" "$h" "$e" \
        "$("$build/gpm" smoothing --operator "$6" --weight "$w" --h "$h" | awk -F'\t' '/^#/ { next } !n++ { next } { print $3 }')"
    done
}
pub=tables/published
tol=0.15  # the agreement tolerance of rate_table
{
  echo "# program = tables/checked_reasons.sh"
  echo "# store = $store"
  echo "# tolerance = $tol (rates)"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  # restores: a run that reproduces the published rate (V_i = dx^2) is part of the check
  # ("yes"), or the diagnostic explains our rate only ("no": the published one stays unexplained).
  printf 'table\tslice\tkey\treason\tevidence\tcheck\trestores\n'
  d=$store/thesis_poisson_diagnostic.tsv
  if [ -f "$d" ] && grep -q tau_predicted "$d"; then
    awk -F'\t' -v tol="$tol" '
      function rate(a, b, ha, hb) { return log(a / b) / log(ha / hb) }
      function abs(x) { return x < 0 ? -x : x }
      FNR == 1 { file++ }
      /^#/ { next }
      !seen[file]++ { for (i = 1; i <= NF; i++) c[file, $i] = i; next }
      file == 1 { pub[$c[1, "h_rule"], $c[1, "weight"]] = $c[1, "numerical"]; keys[++nk] = $c[1, "h_rule"] SUBSEP $c[1, "weight"]; next }
      { k = $c[2, "h_rule"] SUBSEP $c[2, "weight"] SUBSEP $c[2, "level"] SUBSEP $c[2, "variant"]
        err[k] = $c[2, "rel_error"]; tp[k] = $c[2, "tau_predicted"]; hh[k] = $c[2, "h"]
        mm[k] = $c[2, "volume_mismatch"]; ep[k] = $c[2, "eps_smoothing"] }
      END {
        for (i = 1; i <= nk; i++) {
          split(keys[i], kw, SUBSEP); r = kw[1]; w = kw[2]
          a8 = r SUBSEP w SUBSEP 8 SUBSEP "seed1"; a9 = r SUBSEP w SUBSEP 9 SUBSEP "seed1"
          c8 = r SUBSEP w SUBSEP 8 SUBSEP "seed1_cell"; c9 = r SUBSEP w SUBSEP 9 SUBSEP "seed1_cell"
          if (!((a8 in err) && (a9 in err) && (c8 in err) && (c9 in err))) {
            printf "thesis_table4_4\t%s\t%s\tvolume mismatch of (A.10)\tdiagnostic not yet at 2^-8 and 2^-9\tfail\tno\n", r, w
            continue }
          rl = rate(err[a8], err[a9], hh[a8], hh[a9])
          rp = rate(abs(tp[a8]), abs(tp[a9]), hh[a8], hh[a9])
          rc = rate(err[c8], err[c9], hh[c8], hh[c9])
          p = pub[r, w]
          ok = abs(rp - rl) <= tol && abs(rc - p) <= tol
          printf "thesis_table4_4\t%s\t%s\tvolume mismatch of (A.10): V_i = |Omega_H|/N differs from dx^2 by %+.2f%% at 2^-8 and %+.2f%% at 2^-9 (the grid does not tile Omega_H), which scales the discrete Laplacian and adds to the smoothing error\t", r, w, 100 * mm[a8], 100 * mm[a9]
          printf "consistency predicted from eps and the mismatch: %+.4f at 2^-8, %+.4f at 2^-9 (eps alone %.4f, %.4f); error/|predicted| %.2f, %.2f; rate predicted %.2f, reproduced %.2f; with V_i = dx^2: rate %.2f (published %s)\t%s\t%s\n",
            tp[a8], tp[a9], ep[a8], ep[a9], err[a8] / abs(tp[a8]), err[a9] / abs(tp[a9]), rp, rl, rc, p, ok ? "pass" : "fail", abs(rc - p) <= tol ? "yes" : "no" } }' \
      "$pub/thesis_table4_4_long.tsv" "$d"
  fi
  f43=$store/thesis_table4_3.tsv
  if [ -f "$f43" ]; then
    for reading in printed scaled; do
      smoothing_rows "$f43" "$pub/thesis_table4_3_long.tsv" $reading grad case2 grad > "$work/grad_eps.tsv"
      awk -F'\t' -v tol="$tol" -v slice="${reading}_voronoi" '
        function abs(x) { return x < 0 ? -x : x }
        FNR == 1 { file++ }
        file == 1 { if (/^#/) next; if (!hp++) { for (i = 1; i <= NF; i++) p[$i] = i; next }
                    if ($p["operator"] == "grad" && $p["function"] == "case2") pub[$p["weight"]] = $p["numerical"]; next }
        { n[$1]++; hh[$1, n[$1]] = $3; ee[$1, n[$1]] = $4; ep[$1, n[$1]] = $5 }
        END { for (w in n) { if (n[w] != 2 || !(w in pub)) continue
            q1 = ee[w, 1] / ep[w, 1]; q2 = ee[w, 2] / ep[w, 2]
            lh = log(hh[w, 1] / hh[w, 2]); rr = log(ee[w, 1] / ee[w, 2]) / lh; re = log(ep[w, 1] / ep[w, 2]) / lh
            a = abs(q1 - 1) <= 0.01 && abs(q2 - 1) <= 0.01; b = abs(pub[w] - re) > tol
            printf "thesis_table4_3\t%s\t%s grad case2\tthe error is the gradient operator'"'"'s own smoothing error eps_grad(|k|h) of the mode sin 2pi(x+y), with no particle part left; its rate at these h is the operator'"'"'s, and the published rate is out of its reach\t", slice, w
            printf "error/eps_grad %.4f, %.4f at the rate levels; rate of eps_grad %.2f, reproduced %.2f (published %s)\t%s\tno\n", q1, q2, re, rr, pub[w], (a && b) ? "pass" : "fail" } }' \
        "$pub/thesis_table4_3_long.tsv" "$work/grad_eps.tsv"
    done
  fi
  # Table 4.2, Case 1 (v = X^4 + Y^4): the interpolant's smoothing part is known in closed form
  # (gpm smoothing --operator interp-case1).  Where it is a small share of the measured error at
  # both rate levels, the measured two-level rate is the particle part's, not the smoothing
  # order the document prints.
  f42=$store/thesis_table4_2.tsv
  if [ -f "$f42" ]; then
    lv=$(awk '/^# rate_levels = / { print substr($0, 17); exit }' "$pub/thesis_table4_2_long.tsv")
    for reading in printed scaled; do
      smoothing_rows "$f42" "$pub/thesis_table4_2_long.tsv" $reading interp case1 interp-case1 > "$work/interp_sm.tsv"
      awk -F'\t' -v tol="$tol" -v slice="${reading}_voronoi" -v lv="$lv" '
        function abs(x) { return x < 0 ? -x : x }
        FNR == 1 { file++ }
        file == 1 { if (/^#/) next; if (!hp++) { for (i = 1; i <= NF; i++) p[$i] = i; next }
                    if ($p["function"] == "case1") pub[$p["weight"]] = $p["numerical"]; next }
        { n[$1]++; hh[$1, n[$1]] = $3; ee[$1, n[$1]] = $4; sm[$1, n[$1]] = $5 }
        END { split(lv, L, ",")
          for (w in n) { if (n[w] != 2 || !(w in pub)) continue
            q1 = sm[w, 1] / ee[w, 1]; q2 = sm[w, 2] / ee[w, 2]
            lh = log(hh[w, 1] / hh[w, 2]); rr = log(ee[w, 1] / ee[w, 2]) / lh; rs = log(sm[w, 1] / sm[w, 2]) / lh
            # Checked when the smoothing part is at most a fifth of the error at both levels and the
            # published rate is the smoothing part'"'"'s own (what an error made of it alone would give).
            ok = q1 <= 0.2 && q2 <= 0.2 && abs(pub[w] - rs) <= tol && abs(rr - rs) > tol
            printf "thesis_table4_2\t%s\t%s case1\tthe published rate is the order of the interpolant'"'"'s smoothing part (closed form for v = X^4 + Y^4); at the rate levels that part is a small share of the measured error, which is the particle part, so the two-level rate measures how fast the particle part shrinks\t", slice, w
            printf "smoothing part / error %.3f at 2^-%s, %.3f at 2^-%s; rate of the smoothing part %.2f, reproduced %.2f (published %s)\t%s\tno\n", q1, L[1], q2, L[2], rs, rr, pub[w], ok ? "pass" : "fail" } }' \
        "$pub/thesis_table4_2_long.tsv" "$work/interp_sm.tsv"
    done
  fi
  for t in 4_5 4_6 4_7; do
    for r in h10 h10_exact; do
      f=$(heat_file "$store" $t $r) slice=$(heat_label $r)
      [ -f "$f" ] || continue
      # The V_i = dx^2 run counts only under the same Δt rule as the data it is set against.
      cellopt=()
      for cell in "$store/thesis_table${t}_cellvol.tsv" "$store/thesis_table${t}_dtexact_cellvol.tsv"; do
        if [ -f "$cell" ] && [ "$(grep -m1 '^# steps = ' "$cell")" = "$(grep -m1 '^# steps = ' "$f")" ]; then
          cellopt=(--cell "$cell")
        fi
      done
      "$build/thesis_heat_mode_model" --table "${t/_/.}" --data "$f" "${cellopt[@]}" \
        --out "$work/rows.tsv" --rates "$work/rates.tsv" > /dev/null
      awk -F'\t' -v tol="$tol" -v table="thesis_table$t" -v slice="$slice" '
        function abs(x) { return x < 0 ? -x : x }
        FNR == 1 { file++ }
        /^#/ { next }
        !seen[file]++ { for (i = 1; i <= NF; i++) c[file, $i] = i; next }
        file == 1 { pub[$c[1, "weight"] " " $c[1, "theta"]] = $c[1, "numerical"]; next }
        { k = $c[2, "key"]; if (!(k in pub) || pub[k] !~ /^-?[0-9.]+$/) next
          rr = $c[2, "rate_reproduced"]; rp = $c[2, "rate_predicted"]; rn = $c[2, "rate_no_mismatch"]
          rc = $c[2, "rate_cell"]; q1 = $c[2, "ratio_coarse"]; q2 = $c[2, "ratio_fine"]
          a = q1 >= 0.9 && q1 <= 1.1 && q2 >= 0.9 && q2 <= 1.1 && abs(rp - rr) <= tol
          b = rc != "NA" && abs(rc - pub[k]) <= tol
          printf "%s\t%s\t%s\tthe error is the exact solution'"'"'s one Fourier mode after K theta-steps at the discrete decay rate mu(1+delta)(1-eps): time step, smoothing error eps and the volume mismatch delta of (A.10), %+.2f%% and %+.2f%% at the rate levels\t", table, slice, k, 100 * $c[2, "mismatch_coarse"], 100 * $c[2, "mismatch_fine"]
          printf "measured/predicted %.3f, %.3f; rate predicted %.2f, reproduced %.2f; without the mismatch the model gives %.2f; with V_i = dx^2 measured %s (published %s)\t%s\t%s\n", q1, q2, rp, rr, rn, rc == "NA" ? "not run" : sprintf("%.2f", rc), pub[k], (a && b) ? "pass" : "fail", b ? "yes" : "no" }' \
        "$pub/thesis_table${t}_long.tsv" "$work/rates.tsv"
    done
  done
} > "$out.tmp"
mv "$out.tmp" "$out"
