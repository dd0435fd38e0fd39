#!/usr/bin/env bash
# The open set-up questions of the documents and what the stored paper-profile data say about
# each: one row per question, every number read from a data file of the result store, none
# typed.  A question whose runs are not yet in the store says so.
#
# usage: decisions.sh BUILD_DIR STORE_DIR OUT [STORE_SCORE]
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
build=$1 store=$2 out=$3 score=${4:-}
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
    # The same set-up with V_i = dx^2 (the volume mismatch that sets Table 4.4's rates removed).
    cv=$store/thesis_table4_7_cellvol.tsv
    if [ -f "$cv" ]; then
      rates "$cv" 8,9
      c1=$(span reproduced theta 1 "$tmp/r.tsv"); c5=$(span reproduced theta 0.5 "$tmp/r.tsv")
      ev="$ev With V_i = dx^2 (dt = T/K), levels 8/9: theta=1 $c1, theta=1/2 $c5."
    fi
    cx=$store/thesis_table4_7_dtexact_cellvol.tsv
    if [ -f "$cx" ]; then
      rates "$cx" 8,9
      c1=$(span reproduced theta 1 "$tmp/r.tsv"); c5=$(span reproduced theta 0.5 "$tmp/r.tsv")
      ev="$ev With V_i = dx^2 (dt = dt0), levels 8/9: theta=1 $c1, theta=1/2 $c5."
    fi
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

  # --- Imoto Table 1, Lap1/Lap2 at m = 5: smoothing, volume mismatch and particles. -----------
  # Per level 2^-9..2^-12: the plain-grid error beside the prediction |(1 + delta)(1 - eps) - 1|
  # (eps: gpm smoothing, no particles; delta = |Omega_H|/(N dx^2) - 1 of the stored N), the
  # errors of seeds 1-3, and the 2^-11/2^-12 rates of each against the published one.
  if [ -f "$store/imoto_fig5_table1_plain.tsv" ]; then
    areaH=$("$build/gpm" particles --dx 2^-5 | sed -n 's/^# area_H = //p')
    for w in Lap1 Lap2; do
      awk -F'\t' -v w=$w '/^#/ { next } !hdr[FILENAME]++ { for (i=1;i<=NF;i++) c[$i]=i; next }
        $c["weight"] == w && $c["m"] == 5 && $c["level"] >= 9 { print $c["h"] }' \
        "$store"/imoto_fig5_table1.tsv "$store"/imoto_fig5_table1_seed[23].tsv "$store"/imoto_fig5_table1_plain.tsv | sort -u | paste -sd, > "$tmp/hs"
      [ -s "$tmp/hs" ] || continue
      "$build/gpm" smoothing --weight $w --h "$(cat "$tmp/hs")" | awk -F'\t' '!/^#/ && $1 != "h"' > "$tmp/eps_$w.tsv"
      awk -F'\t' -v w=$w -v A="$areaH" -v pubfile="$pub/imoto_table1.tsv" '
        function abs(x) { return x < 0 ? -x : x }
        BEGIN { while ((getline line < pubfile) > 0) { if (line ~ /^#/) continue; split(line, f, "\t")
                  if (f[2] == w && f[3] == 5) pubrate = f[4] } }
        FILENAME ~ /eps_/ { eps[$1] = $3; next }
        /^#/ { next } !hdr[FILENAME]++ { for (i=1;i<=NF;i++) c[$i]=i; next }
        $c["weight"] != w || $c["m"] != 5 || $c["level"] < 9 { next }
        { v = FILENAME; sub(/.*imoto_fig5_table1_?/, "", v); sub(/\.tsv$/, "", v); if (v == "") v = "seed1"
          l = $c["level"]; e[l, v] = $c["rel_error"]; hh[l] = $c["h"]; N[l] = $c["N"]; dx[l] = $c["dx"]; L[l] = 1 }
        END { ev = ""
          for (l = 9; l <= 12; l++) if (l in L) {
            d = A / (N[l] * dx[l] * dx[l]) - 1; p = abs((1 + d) * (1 - eps[hh[l]]) - 1); pred[l] = p; ep[l] = eps[hh[l]]
            ev = ev sprintf(" 2^-%d: plain %s, predicted %.3e (eps %.3e, delta %+.2e); seeds %s %s %s;", l,
                            ((l, "plain") in e) ? sprintf("%.3e", e[l, "plain"]) : "not computed", p, eps[hh[l]], d,
                            ((l, "seed1") in e) ? sprintf("%.3e", e[l, "seed1"]) : "-", ((l, "seed2") in e) ? sprintf("%.3e", e[l, "seed2"]) : "-",
                            ((l, "seed3") in e) ? sprintf("%.3e", e[l, "seed3"]) : "-") }
          r = " rates 2^-11/2^-12:"
          split("seed1 seed2 seed3 plain", vs, " ")
          for (j = 1; j <= 4; j++) if (((11, vs[j]) in e) && ((12, vs[j]) in e)) r = r sprintf(" %s %.2f", vs[j], log(e[11, vs[j]] / e[12, vs[j]]) / log(hh[11] / hh[12]))
          if ((11 in L) && (12 in L)) r = r sprintf(", predicted (plain) %.2f, eps alone %.2f (published %s).", log(pred[11] / pred[12]) / log(hh[11] / hh[12]), log(ep[11] / ep[12]) / log(hh[11] / hh[12]), pubrate)
          printf "Imoto Table 1, %s at m = 5: smoothing, volume mismatch and particles\t%s%s\t%s\n", w, ev, r,
            "the plain-grid error is the consistency error |(1 + delta)(1 - eps) - 1| of the operator (no particle part); the jittered seeds add the particle part, which shrinks fastest between 2^-11 and 2^-12 and so steepens the two-level rate" }' \
        "$tmp/eps_$w.tsv" "$store"/imoto_fig5_table1.tsv "$store"/imoto_fig5_table1_seed[23].tsv "$store"/imoto_fig5_table1_plain.tsv
    done
  fi

  # --- Imoto Table 1, Lap1/Lap2 at m = 5: where in Omega the maximum sits. -------------------
  # From tables/imoto_where.sh's runs (gpm trunc, which reports the particle of the maximum):
  # per weight, the distance of that particle to the boundary of Omega in units of h over the
  # jittered runs and over the plain grid, and how closely those runs' errors equal the
  # stored Table 1 rows of the same (level, realization).
  where=$store/imoto_m5_where.tsv
  if [ -f "$where" ]; then
    for w in Lap1 Lap2; do
      awk -F'\t' -v w=$w '
        /^#/ { next } !hdr[FILENAME]++ { for (i=1;i<=NF;i++) c[$i]=i; next }
        FILENAME ~ /where/ { if ($c["weight"] != w) next
          key = $c["variant"] SUBSEP $c["level"]; e[key] = $c["rel_error"]; d = $c["worst_to_boundary_over_h"] + 0
          if ($c["variant"] == "plain") { np++; pmax = (np == 1 || d > pmax) ? d : pmax }
          else { nj++; jmin = (nj == 1 || d < jmin) ? d : jmin; jmax = (nj == 1 || d > jmax) ? d : jmax }
          L[$c["level"] + 0] = 1; next }
        $c["weight"] == w && $c["m"] == 5 {
          v = FILENAME; sub(/.*imoto_fig5_table1_?/, "", v); sub(/\.tsv$/, "", v); if (v == "") v = "seed1"
          s[v SUBSEP $c["level"]] = $c["rel_error"] }
        END { dev = 0; n = 0; lv = ""
          for (l = 1; l <= 20; l++) if (l in L) lv = lv (lv == "" ? " 2^-" : ", 2^-") l
          for (k in e) if (k in s) { n++; r = e[k] / s[k] - 1; if (r < 0) r = -r; if (r > dev) dev = r }
          if (nj + np == 0) exit
          printf "Imoto Table 1, %s at m = 5: where the maximum sits\t", w
          printf "jittered runs (%d, levels%s): the largest error sits %.1f h to %.1f h inside the boundary of Omega; plain grid (%d runs): its maximum lies within %.2f h of the boundary (it is attained along whole lines where |Lap u| is largest, so its place is not informative); the runs reproduce %d stored errors to %.1e (relative)\t",
                 nj, lv, jmin, jmax, np, pmax, n, dev
          printf "%s\n", (jmin >= 1 ? "the particle part of the error is an interior effect (no boundary layer): the steep 2^-11/2^-12 rate is not a boundary artefact" : "the largest error sits within h of the boundary in some jittered run: a boundary effect cannot be excluded") }' \
        "$where" "$store"/imoto_fig5_table1.tsv "$store"/imoto_fig5_table1_seed[23].tsv "$store"/imoto_fig5_table1_plain.tsv
    done
  fi

  # --- The reading of each table's set-up (h printed or scaled, h10 or h15, dt = T/K or dt0):
  # per table, how many of its published rates each stored reading reproduces (store_score.tsv:
  # agrees, non-convergence, seed band, checked reason), and the one the scoreboard counts.
  if [ -n "$score" ] && [ -f "$score" ]; then
    awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
      $c["setup"] == "document" && $c["table"] != "total" {
        t = $c["table"]; g = $c["agrees"] + $c["non_convergence"] + $c["in_seed_band"] + $c["checked_reason"]
        ev[t] = ev[t] sprintf(" %s: %d of %d reproduced (%d not yet computed);", $c["slice"], g, $c["rates"], $c["not_computed"])
        n[t]++; if ($c["counted"] == "yes") pick[t] = $c["slice"]; if (!(t in seen)) { seen[t] = 1; order[++m] = t } }
      END { for (i = 1; i <= m; i++) { t = order[i]; if (n[t] < 2) continue
        printf "%s: which reading of the set-up the document ran\t%s\tidentified: %s (the rule of paper/04-setup-rule.md: the fingerprint where one decides, else as printed; the judged rates play no part); every reading stays in the data\n", t, ev[t], pick[t] } }' "$score"
  fi

  # --- Omega_H: the square or the rounded H-neighbourhood; jittered particles mirrored or dropped.
  # From the package's own grid (gpm particles, plain grid): the nodes in the square Omega_H,
  # those within distance H of Omega (the rounded H-neighbourhood the documents define), and
  # the expected number of particles the jitter moves out of Omega_H (the thesis' X_{N,H} keeps
  # only points in Omega_H; the package mirrors them back), with the volume mismatch of (A.10)
  # either way.  The thesis prints N = 1,521 at dx = 2^-5 (Figure 4.1).
  amp=$("$build/gpm" particles --dx 2^-5 | sed -n 's/^# jitter = //p')
  ev=""
  for k in 5 7 8 9; do
    ev="$ev $("$build/gpm" particles --dx 2^-$k --jitter 0 | awk -F'\t' -v k=$k -v a="$amp" '
      /^# dx_value = / { dx = $0; sub(/.*= /, "", dx) } /^# H = / { H = $0; sub(/.*= /, "", H) }
      /^# area_H = / { A = $0; sub(/.*= /, "", A) }
      /^#/ { next } !h++ { next }
      { x = $1; y = $2; n++
        ox = x < 0 ? -x : (x > 1 ? x - 1 : 0); oy = y < 0 ? -y : (y > 1 ? y - 1 : 0)
        if (ox * ox + oy * oy < H * H) r++
        ex = x + H < 1 + H - x ? x + H : 1 + H - x; ey = y + H < 1 + H - y ? y + H : 1 + H - y
        px = ex < a * dx ? (a * dx - ex) / (2 * a * dx) : 0; py = ey < a * dx ? (a * dx - ey) / (2 * a * dx) : 0
        E += 1 - (1 - px) * (1 - py) }
      END { printf "2^-%d: N = %d in the square, %d in the rounded neighbourhood; %.0f expected to leave; volume mismatch %+.3f%% mirrored, %+.3f%% dropped;", k, n, r, E, 100 * (A / (n * dx * dx) - 1), 100 * (A / ((n - E) * dx * dx) - 1) }')"
  done
  printf 'Omega_H: the square (-H, 1+H)^2 or the rounded H-neighbourhood of Omega; jittered particles that leave Omega_H mirrored back or dropped\t%s\tthe square: Imoto Sec. 5 sets Omega_H = (-0.1, 1.1)^2 in so many words, and its node count at 2^-5 is the N printed with Figure 4.1; particles mirrored (kept), the dropped alternative changes the volume mismatch by the amounts listed\n' "$ev"

  # --- w^bell of the heat and Poisson studies (thesis §4.2-4.3). -------------------------------
  printf 'w^bell of Sections 4.2-4.3: which registry weight\tthesis 4.1.2: the operators with the quartic polynomial are those of SPH with the bell-shaped kernel (Remark A.1: w = -(r/d) d/dr w^S); the unit test "quartic_polynomial is -(r/2) d/dr of the bell-shaped kernel" checks the registry weight against central differences of (5/pi)(1+3r)(1-r)^3 at r = 0.05..0.95\tquartic_polynomial (and piecewise cubic / quintic polynomial for w^cubic, w^quintic, by the same remark)\n'

  # --- The gradient norm (decided by the documents' definitions). ----------------------------
  printf 'Gradient error norm\tImoto Sec. 1 defines |x| as the Euclidean norm; the thesis writes [l-inf(Omega)]^2 for vector fields; test "gradient error: Euclidean norm, brute force reference" checks the fused pass against a brute-force Euclidean evaluation and that the component-wise value differs\tEuclidean length of the error vector, maximum over particles in Omega (all gradient data since this change)\n'
} > "$out.tmp"
mv "$out.tmp" "$out"
