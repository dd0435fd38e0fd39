#!/usr/bin/env bash
# Rewrites tests/paper/known_unexplained.tsv from the store's current verdicts: one row per
# paper-scale rate of either board that differs without a checked reason, with a note per group of
# what is known about it (edit the notes below when a diagnostic lands).  Run by hand after
# new rows enter the store; check_verdicts.sh (ctest paper_verdicts) then passes again.
# usage: regenerate_known_unexplained.sh BUILD_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/gpm" store-rates --store results/paper --out "$tmp/r.tsv"
# A rate is open where the judge says so (columns open, open_identified: verdicts.cpp's
# spelling table is the one place the set is written).
awk -F'\t' '
function note(t, s, k) {
  if (t == "imoto_table1" && k ~ / 3$/) return "m = 3: seed 1 differs and the published rate lies outside the band of the stored seeds (five since seed 5 landed) at 2^-11/2^-12 (seed_band column); no diagnostic for this row yet"
  if (t == "imoto_table1" && k ~ /Lap[12] 5$/) return "m = 5: the plain-grid error equals |(1+delta)(1-eps)-1| (decisions: imoto Lap m = 5, eps alone gives 2.00); the particle part of the seeds falls steeply between 2^-11 and 2^-12 and steepens the rate; the largest jittered error sits inside Omega for Lap1 (2.2-6.6 h from the boundary, imoto_m5_where.tsv), for Lap2 once on the boundary; why the document did not see the particle part is open"
  if (t == "imoto_table1" && k ~ /(Pi3|Grad3) 5$/) return "m = 5, weight of order n = 3: every stored seed lies above the published rate (about 7.5; seed_band column); the plain grid steeper still (12.5-13.1); no diagnostic yet"
  if (t == "imoto_table1" && k ~ / 5$/) return "m = 5: every stored seed lies below the published rate of about 2.0 (seed_band column), the plain grid 1.2-1.6 (flatter): consistent with the volume mismatch of |Omega_H|/N seen for Lap1/Lap2, no checked diagnostic yet"
  if (t == "thesis_table4_7") return "dt = dt0 = 0.5h, theta = 1/2: the one-mode model (thesis_heat_mode_model: time step, smoothing eps, volume mismatch of (A.10)) predicts the stored errors to 3% and the reproduced rate (checked_reasons.tsv); without the mismatch it gives 2.00, the published value; the check waits for the measured rate with V_i = dx^2 under dt = dt0 (thesis_table4_7_dtexact_cellvol)"
  if (t == "thesis_table4_2" && k ~ /cubic_spike case1/) return "cubic spike, Case 1 (the quartic): the error falls about fivefold per level from 2^-9 to 2^-12 (as dx^2.3, about 12 in h = c dx^(1/5)) while Case 2 gives the published 4.27; the plain grid with Voronoi volumes falls the same way (gpm trunc: 2.4e-4, 4.3e-5, 7.8e-6 at 2^-9..2^-11, largest at a corner of Omega), so the Case 1 error there is a corner error, not the h^4 smoothing part; no checked diagnostic yet"
  if (t == "thesis_table4_6" && k ~ / 0$/) return "theta = 0, dt = 0.5h^2, unstable, run to T without a growth guard: the error grows by a per-step factor independent of h, so the two-level rate counts the extra steps; under the printed h10 (K = 16 -> 22) the rate is about a sixth of the printed one, only its sign agrees; under h15 (K = 86 -> 122) it comes within 1%, which is why these rates identify the reading (paper/04-setup-rule.md) and count as fingerprint on the identified board"
  if (t == "thesis_table4_6" && k ~ / 0.5$/) return "dt = 0.5h^2, theta = 1/2: the one-mode model (thesis_heat_mode_model) predicts the stored errors to 3% and the reproduced rate, set by the volume mismatch of (A.10) changing sign between 2^-8 and 2^-9; without the mismatch the model gives about 1.9 (the smoothing error, O(h^2)) and the run with V_i = dx^2 measures the same where it has run (checked_reasons.tsv: quartic 1.95): the published 4.3-4.6 lies above both and above the theoretical 2"
  if (t == "thesis_table4_6" && k ~ / 1$/) return "dt = 0.5h^2, theta = 1: the one-mode model predicts the stored errors to 3% and the reproduced rate (time step with the sign change of the volume mismatch); without the mismatch it gives 1.82 against the published 1.94-2.06; the rate measured with V_i = dx^2 (thesis_table4_6_cellvol) decides the check where it has run"
  if (t == "thesis_table4_5") return "dt = 0.0025h^2 (K in the thousands, so the time step plays no part): at 2^-7 the one-mode model predicts that smoothing and volume mismatch nearly cancel ((1+delta)(1-eps) close to 1), and the measured error, the particle part, is several times the model; at 2^-8 the model accounts for the error (checked_reasons.tsv), so the reproduced rate follows the sign change of the mismatch, not h. Without the mismatch (V_i = dx^2, stored at 2^-7/2^-8) the rates are 2.3-3.0 under h10 and 5.1-7.0 under the identified reading (h15, dt = dt0), 0.2-1.3 from the published ones; under h15 with (A.10) they are 9.4-11.1. With V_i = dx^2 the three theta differ by at most 0.3 (K in the thousands: their errors differ by at most 10 %), while the published quartic rates fall from 6.63 (theta = 0) to 4.62 (theta = 1): that spread is not a time-step effect of these runs; no diagnostic for the remaining gap"
  if (t == "thesis_table4_2") return "Table 4.2 at 2^-11/2^-12: no diagnostic for this row yet"
  if (t == "thesis_table4_4") return "Poisson problem: under h10 the checked volume-mismatch reason of the report applies where its diagnostic passes; this row has none that passes at the rate levels"
  return "open: no diagnostic yet" }
BEGIN { print "# Paper-scale rates that differ from the published ones without a checked reason (tests/paper/check_verdicts.sh)."
        print "# One row per rate of either board (the reading as printed, the identified one): remove a row when its rate agrees, enters the seed band or gets a checked reason; the suite fails on a stale row."
        print "# Written by tests/paper/regenerate_known_unexplained.sh (edit the notes there)."
        printf "table\tslice\tkey\topen\n" }
/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
$c["setup"] == "document" && (($c["printed"] == "yes" && $c["open"] == "yes") ||
                               ($c["identified"] == "yes" && $c["open_identified"] == "yes")) {
  printf "%s\t%s\t%s\t%s\n", $c["table"], $c["slice"], $c["key"], note($c["table"], $c["slice"], $c["key"]) }' \
  "$tmp/r.tsv" > tests/paper/known_unexplained.tsv
bash tests/paper/check_verdicts.sh "$build" . | tail -2
