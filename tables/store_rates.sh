#!/usr/bin/env bash
# The documents' rates from the committed result store (results/paper), whatever profile the
# report is built for: rate_table on every stored study file (one slice per reading of h and
# volume choice, as the profile's own rate tables), merged into one file for the report.
# No study is run.  Columns: table, slice, setup, key, published, reproduced, levels, status.
# `setup` says whether the slice is one of the documents' own set-ups (both readings of h
# are: which one the thesis ran is open) or a variant beyond them (uniform volumes where the
# thesis uses Voronoi volumes), which has no published value to agree with.
# SUMMARY lists, per stored file, its rows, levels, and how many rows the current code made,
# how many a recorded re-check carried over, and how many come from other code.
#
# SCORE counts the verdicts per (table, slice).
#
# Verdicts of a document row (`verdict` column), in this order:
#   agrees                      within rate_table's tolerance of the published rate, where the
#                               documents claim convergence;
#   non-convergence reproduced  within tolerance where the published theoretical rate is NA
#                               (Imoto's m = 1 rows: the rate is about 0 or -1, a different claim);
#   indeterminate               the published rate lies inside the seed band, but the band has
#                               fewer than 5 realizations or is wider than the tolerance;
#   inside seed band            differs for seed 1, but the published rate lies between the
#                               smallest and largest rate of the stored seeds 1-3 (Imoto, and
#                               the thesis tables where seeds 2 and 3 are stored);
#   differs, checked reason     a reason in CHECKED (checked_reasons.sh) whose diagnostic passed
#                               and includes a run that restores the published rate;
#   our rate explained, the published one not
#                               a passed diagnostic that accounts for our rate only;
#   differs, unexplained        none of the above;
#   not computed                a level missing (or only other levels than the documents', for a
#                               reading the catalog trims);
#   undefined                   no finite rate (a run that overflowed): never reproduced.
# Non-convergence is reproduced only from a computed rate: within tolerance where the document
# claims none (theoretical NA), or, where it prints an unstable run (theoretical "unstable"),
# when ours is unstable too by a stated measure: error above the solution (rel_error > 1) at
# both rate levels and growing as h falls (rate < 0).
#
# Two scoreboards, each over every published rate once (paper/04-setup-rule.md):
#   printed = yes   the reading as the text prints it (imoto: seed 1; Tables 4.1-4.3: printed h,
#                   Voronoi volumes; Tables 4.4-4.7: h10, V_i = |Omega_H|/N, dt = T/K);
#   identified = yes the reading the documents' fingerprint identifies (setup_identification:
#                   Chapter 4's h rule, volumes and time step from Table 4.6's theta = 0 rates;
#                   elsewhere as printed); the fingerprint rates themselves are counted as
#                   `fingerprint` on that board, not as reproduced.
# `counted` = identified (the board the report leads with).  IDENT (written) is
# setup_identification's table, the fingerprint evidence.
#
# usage: store_rates.sh BUILD_DIR STORE_DIR OUT SUMMARY SCORE [CHECKED [IDENT]]
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
build=$1 store=$2 out=$3 summary=$4 score=$5 checked=${6:-/dev/null} ident=${7:-}
tmp=$(mktemp -d)
# Header lines every output carries (the report prints them under each table).
rev=$(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
provenance() {
  printf '# profile = paper (the committed store %s)\n# seed = 1\n# git_revision = %s\n# written_utc = %s\n' \
    "$store" "$rev" "$(date -u +%Y-%m-%dT%H:%M:%SZ)"
}
trap 'rm -rf "$tmp"' EXIT
pub=tables/published

# rate TABLE SLICE DATA PUBLISHED KEYS: one rate table into $tmp/rates/TABLE.SLICE.tsv
mkdir "$tmp/rates"
rate() {
  "$build/rate_table" --data "$3" --published "$4" --key "$5" --levels published \
    --out "$tmp/rates/$1.$2.tsv" >/dev/null
}
# slice FILE READING VOLUMES: the rows of one (h reading, volumes) pair, header kept
slice() {
  awk -F'\t' -v r="$2" -v v="$3" '/^#/ { print; next }
    !h++ { for (i = 1; i <= NF; i++) c[$i] = i; print; next }
    $c["h_reading"] == r && $c["volumes"] == v' "$1"
}
source "$(dirname "$0")/store_lib.sh"  # finite, heat_file, heat_label

# Seed 1 is the reproduction; the files …_seed2, …_seed3 (where stored) are other jitter
# realizations at the rate levels, slices named <slice>_seedN, for the seed band.
for t in 4_1 4_2 4_3; do
  key=weight,function
  [ $t = 4_3 ] && key=weight,operator,function
  for v in "" _seed2 _seed3; do
    f=$store/thesis_table$t$v.tsv
    [ -f "$f" ] || continue
    for s in printed_voronoi scaled_voronoi printed_uniform scaled_uniform; do
      slice "$f" "${s%_*}" "${s#*_}" > "$tmp/slice.tsv"
      [ "$(grep -vc '^#' "$tmp/slice.tsv")" -gt 1 ] || continue
      rate "thesis_table$t" "$s$v" "$tmp/slice.tsv" "$pub/thesis_table${t}_long.tsv" "$key"
    done
  done
done
for v in all seed2 seed3 cellvol; do  # cellvol: the reading V_i = dx^2, slices h10_cell, h15_cell
  f=$store/thesis_table4_4.tsv
  [ $v = all ] || f=$store/thesis_table4_4_$v.tsv
  [ -f "$f" ] && rate thesis_table4_4 $v "$f" "$pub/thesis_table4_4_long.tsv" h_rule,weight
done
# A (weight, theta) series that is unstable at both rate levels - it blew up (growth beyond
# the run's limit) or its error exceeds the solution (rel_error > 1) - has no rate; where the
# document prints an unstable run there (theoretical "unstable"), that is what it reports.
: > "$tmp/blown.tsv"
for t in 4_5 4_6 4_7; do
  for r in $heat_readings; do
    f=$(heat_file "$store" $t $r)
    [ -f "$f" ] || continue
    finite "$f" > "$tmp/finite.tsv"
    rate "thesis_table$t" "$r" "$tmp/finite.tsv" "$pub/thesis_table${t}_long.tsv" weight,theta
    sl=$r
    awk -F'\t' -v t="thesis_table$t" -v sl="$sl" '
      FNR == 1 { file++ }
      file == 1 && /^# rate_levels = / { split(substr($0, 17), rl, ","); next }
      /^#/ { next }
      !seen[file]++ { for (i = 1; i <= NF; i++) c[file, $i] = i; next }
      file == 2 && ($c[2, "level"] == rl[1] || $c[2, "level"] == rl[2]) &&
        ($c[2, "blew_up"] == "yes" || $c[2, "rel_error"] + 0 > 1) {
        k = $c[2, "weight"] " " $c[2, "theta"]; n[k]++
        e = $c[2, "blew_up"] == "yes" ? "blew up at step " $c[2, "blowup_step"] " of " $c[2, "K"] \
                                      : sprintf("error %.3g after %d steps", $c[2, "rel_error"], $c[2, "K"])
        ev[k] = ev[k] (ev[k] == "" ? "" : "; ") "2^-" $c[2, "level"] ": " e }
      END { for (k in n) if (n[k] == 2) printf "%s\t%s\t%s\tunstable at both rate levels (%s)\n", t, sl, k, ev[k] }' \
      "$pub/thesis_table${t}_long.tsv" "$f" >> "$tmp/blown.tsv"
  done
done
# imoto: seed 1 is the reproduction; seeds 2-6 (where stored) and the plain grid (no jitter)
# show how much of a rate is one realization's particle noise; cellvol (where stored) is the
# delta-free error, V_i = dx^2 instead of |Omega_H|/N.
for v in all seed2 seed3 seed4 seed5 seed6 plain cellvol; do
  f=$store/imoto_fig5_table1.tsv
  [ $v = all ] || f=$store/imoto_fig5_table1_$v.tsv
  if [ -f "$f" ]; then
    rate imoto_table1 $v "$f" "$pub/imoto_table1.tsv" operator,weight,m
  fi
done

# The reading of Chapter 4 that Table 4.6's theta = 0 rates identify (paper/04-setup-rule.md).
ident=${ident:-$tmp/setup_identification.tsv}
"$build/setup_identification" --store "$store" --published "$pub/thesis_table4_6_long.tsv" --out "$ident" >/dev/null
identified=$(sed -n 's/^# identified = //p' "$ident")
# Table 4.4 (Poisson, no time step) takes the identified h rule and volumes.
identified_h=$(sed -n 's/^# decided_h_rule = \([a-z0-9]*\).*/\1/p' "$ident")
[ -n "$identified_h" ] || identified_h=h10
[ "$(sed -n 's/^# decided_volumes = \([a-z]*\).*/\1/p' "$ident")" = cell ] && identified_h=${identified_h}_cell

# Merge: the key columns of each table joined into one "key" cell; columns found by name.
# The seed band of a key is the range of the rates of its seed-1, seed-2 and seed-3 slices.
{
  echo "# program = tables/store_rates.sh"
  provenance
  echo "# store = $store"
  echo "# checked_reasons = $checked"
  echo "# note = rates at the documents' levels from the committed paper-profile rows; status from rate_table (tolerance in its header); verdict as listed in tables/store_rates.sh"
  printf 'table\tslice\tsetup\tkey\tpublished\treproduced\tlevels\tstatus\tseed_band\tverdict\treason\tprinted\tidentified\tverdict_identified\tcounted\n'
  for r in "$tmp"/rates/*.tsv; do
    [ -e "$r" ] || continue
    name=$(basename "$r" .tsv)
    awk -F'\t' -v t="${name%%.*}" -v s="${name#*.}" '
      /^# key = / { nk = split(substr($0, 9), keys, ",") }
      # Whether the published file itself has a theoretical column (rate_table writes NA
      # when it has none; only a printed NA means "no convergence claimed").
      /^# published = / { f = substr($0, 15); claims = 0
        while ((getline line < f) > 0) if (line !~ /^#/) { claims = line ~ /(^|\t)theoretical(\t|$)/; break }
        close(f) }
      /^#/ { next }
      !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
      { k = $c[keys[1]]; for (j=2;j<=nk;j++) k = k " " $c[keys[j]];
        seed = match(s, /seed[0-9]+$/) ? substr(s, RSTART) : ""
        setup = s ~ /uniform/ ? "beyond the document (uniform volumes)" \
              : seed != "" ? "another jitter realization" : s == "plain" ? "plain grid (no jitter)" \
              : (t == "imoto_table1" && s == "cellvol") ? "delta-free volumes (V_i = dx^2)" : "document"
        sl = s
        # Table 4.4 prints one rate per weight for both readings of h: one slice per reading.
        if (t == "thesis_table4_4") { sl = $c["h_rule"] (seed != "" ? "_" seed : "") (s == "cellvol" ? "_cell" : ""); k = $c["weight"] }
        status = setup == "document" ? $c["status"] : "no published value for this set-up"
        printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", t, sl, setup, k, $c["published"], $c["reproduced"], $c["levels"], status, claims ? $c["theoretical"] : "" }' "$r"
  done > "$tmp/merged.tsv"
  cp "$tmp/merged.tsv" "$tmp/merged_again.tsv"  # second pass (awk tells files by name)
  # rate_table's agreement tolerance, as its files record it (one number, one source).
  tol=$(sed -n 's/^# tolerance = //p' "$(ls "$tmp"/rates/*.tsv | head -1)")
  awk -F'\t' -v tol="$tol" '
    function num(x) { return x ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ }
    FILENAME == ARGV[1] { blown[$1, $2, $3] = $4; next }
    FILENAME == ARGV[2] { if (/^#/) next; if (!hc++) { for (i=1;i<=NF;i++) cc[$i]=i; next }
                if ($cc["check"] == "pass") { ok[$cc["table"], $cc["slice"], $cc["key"]] = $cc["restores"] == "yes" ? 2 : 1
                  why[$cc["table"], $cc["slice"], $cc["key"]] = $cc["reason"] ": " $cc["evidence"] }
                next }
    # The band of a (table, slice, key): the rates of its seed-1 slice and of the same slice
    # of the other seeds (slice_seedN; imoto: seedN beside "all").
    function base(t, s) { sub(/_?seed[0-9]+$/, "", s); return (s == "" && t == "imoto_table1") ? "all" : s }
    FILENAME == ARGV[3] { seedslice = $3 == "document" || $3 == "another jitter realization"
                if (seedslice && num($6)) { k = $1 SUBSEP base($1, $2) SUBSEP $4; n[k]++
                  if (!(k in lo) || $6 + 0 < lo[k]) lo[k] = $6 + 0
                  if (!(k in hi) || $6 + 0 > hi[k]) hi[k] = $6 + 0 }
                next }
    { k = $1 SUBSEP base($1, $2) SUBSEP $4; band = (n[k] >= 2) ? sprintf("%.2f to %.2f (%d seeds)", lo[k], hi[k], n[k]) : ""
      v = $8; reason = ""
      if ($3 == "document") {
        if ($8 == "agrees") v = $9 == "NA" ? "non-convergence reproduced" : "agrees"
        else if ($8 ~ /^differs/ && $9 == "unstable" && (($1, $2, $4) in blown) && num($6) && $6 + 0 < 0 && $5 + 0 < 0) {
          v = "non-convergence reproduced"; reason = "both unstable: " blown[$1, $2, $4] ", rate < 0" }
        else if ($8 ~ /^differs/) {
          # Inside the band of the jitter realizations: a verdict only with at least 5 of them
          # and a band no wider than the tolerance; otherwise the seeds cannot decide.
          if (band != "" && num($5) && $5 + 0 >= lo[k] && $5 + 0 <= hi[k]) {
            if (n[k] >= 5 && hi[k] - lo[k] <= tol) v = "inside seed band"
            else { v = "indeterminate"  # (more seeds only widen a band already too wide)
              reason = hi[k] - lo[k] > tol ? sprintf("band of %d seeds %.2f wide, wider than the tolerance %.2f: the realizations cannot decide", n[k], hi[k] - lo[k], tol) \
                                           : sprintf("published inside the band of %d seeds; 5 are needed to decide", n[k]) } }
          # A checked reason whose check includes a run that restores the published rate; one
          # that explains only our rate leaves the published one unexplained, and says so.
          else if (($1, $2, $4) in ok) { v = ok[$1, $2, $4] == 2 ? "differs, checked reason" : "our rate explained, the published one not"; reason = why[$1, $2, $4] }
          else v = "differs, unexplained" }
        else if ($8 == "not-computed" && (($1, $2, $4) in blown)) {
          v = "undefined"; reason = "no finite rate: " blown[$1, $2, $4] }
        else if ($8 == "not-computed") v = "not computed"
        # A rate from other levels than those of the document (a reading the catalog trims before
        # the finest level): shown, but not computed at the levels of the document.
        else if ($8 == "other-levels") { v = "not computed"; reason = "rate from levels " $7 " only (the catalog trims this reading before the finest level of the document)" } }
      else v = "not counted"
      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", $1, $2, $3, $4, $5, $6, $7, $8, band, v, reason }' \
    "$tmp/blown.tsv" "$checked" "$tmp/merged.tsv" "$tmp/merged_again.tsv" > "$tmp/verdicts.tsv"
  # The two boards (header above): which slice of each table is the reading as printed, and
  # which the fingerprint identified (Chapter 4 only; undecided: as printed).
  awk -F'\t' -v id="$identified" -v idh="$identified_h" '
    BEGIN { OFS = "\t"; split("imoto_table1 all thesis_table4_1 printed_voronoi thesis_table4_2 printed_voronoi thesis_table4_3 printed_voronoi thesis_table4_4 h10 thesis_table4_5 h10 thesis_table4_6 h10 thesis_table4_7 h10", p, " ")
      for (i = 1; i in p; i += 2) { printed[p[i]] = p[i + 1]; ident[p[i]] = p[i + 1] }
      if (id != "NA") { ident["thesis_table4_4"] = idh; for (t = 5; t <= 7; t++) ident["thesis_table4_" t] = id } }
    { pr = $3 == "document" && printed[$1] == $2; ie = $3 == "document" && ident[$1] == $2
      # The fingerprint rates identified the reading: on that board they are evidence, not results.
      vi = (ie && id != "NA" && $1 == "thesis_table4_6" && $4 ~ / 0$/) ? "fingerprint" : $10
      print $0, pr ? "yes" : "no", ie ? "yes" : "no", vi, ie ? "yes" : "no" }' "$tmp/verdicts.tsv"
} > "$out.tmp"
mv "$out.tmp" "$out"

# Where the stored rows come from, file by file.
{
  echo "# program = tables/store_rates.sh (summary)"
  provenance
  echo "# store = $store"
  echo "# current = rows whose code column is the fingerprint of this build's program (gpm fingerprint)"
  printf 'file\tprogram\trows\tlevels\tcurrent_computed\tcurrent_by_recheck\tother_code\tmade_on\n'
  for f in "$store"/*.tsv; do
    [ -e "$f" ] || continue
    prog=$(sed -n 's/^# program = //p' "$f" | head -1)
    # A file of a script (imoto_where.sh) has no program fingerprint and no code column.
    code=$("$build/gpm" fingerprint "$prog" 2>/dev/null | awk -F'\t' 'NR>2 { print $2 }') || code=""
    awk -F'\t' -v file="$(basename "$f")" -v prog="$prog" -v code="$code" '
      /^#/ { next }
      !h++ { for (i=1;i<=NF;i++) c[$i]=i; if (!("code" in c)) exit; next }
      { n++; lv[$c["level"]]=1; m[$c["made_on"]]=1
        if ($c["code"] != code) other++
        else if ($c["checked"] ~ /recheck/) carried++
        else fresh++ }
      END { if (!("code" in c)) exit  # a derived file (cost, rates input), not a study file
            l=""; for (k=1; k<=20; k++) if (k in lv) l = l (l=="" ? "" : ",") k
            mo=""; for (k in m) mo = mo (mo=="" ? "" : "; ") k
            printf "%s\t%s\t%d\t%s\t%d\t%d\t%d\t%s\n", file, prog, n, l, fresh, carried, other, mo }' "$f"
  done
} > "$summary.tmp"
mv "$summary.tmp" "$summary"

# Verdict counts per table and slice, in the order the rates file lists them (the matrix of
# readings: counts and the mean |reproduced - published|), then the two boards' totals.  A
# board whose reading of a table has no stored rows counts its published rates not computed.
awk -F'\t' '
  BEGIN { OFS = "\t"; ncat = split("agrees|non-convergence reproduced|inside seed band|differs, checked reason|our rate explained, the published one not|differs, unexplained|not computed|undefined|fingerprint|indeterminate", cat, "|") }
  function num(x) { return x ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ }
  /^#/ { next }
  !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
  { t = $c["table"]; k = t OFS $c["slice"] OFS $c["setup"]
    if (!(k in n)) order[++m] = k
    # The identified slice counts with its own verdicts (fingerprint rows), the others as they are.
    n[k]++; st[k, $c["identified"] == "yes" ? $c["verdict_identified"] : $c["verdict"]]++
    if (num($c["reproduced"]) && num($c["published"])) { d = $c["reproduced"] - $c["published"]; sd[k] += d < 0 ? -d : d; nd[k]++ }
    if ($c["printed"] == "yes") { pk[k] = 1; B["printed", t] = 1; npub[t]++; for (j = 1; j <= ncat; j++) if ($c["verdict"] == cat[j]) T["printed", j]++ }
    if ($c["identified"] == "yes") { ik[k] = 1; B["identified", t] = 1; for (j = 1; j <= ncat; j++) if ($c["verdict_identified"] == cat[j]) T["identified", j]++ } }
  function counts(kk, j, s) { s = ""; for (j = 1; j <= ncat; j++) s = s OFS (st[kk, cat[j]] + 0); return s }
  END {
    print "# program = tables/store_rates.sh (score)"
    while ((getline line < "/dev/stdin") > 0) print line
    print "# boards = printed: every set-up detail as the text prints it; identified: the readings of paper/04-setup-rule.md (fingerprint: a published rate that identified the reading)"
    print "table", "slice", "setup", "printed", "identified", "counted", "rates", "agrees", "non_convergence", "in_seed_band", "checked_reason", "explained_ours", "unexplained", "not_computed", "undefined", "fingerprint", "indeterminate", "mean_abs_diff"
    for (i=1;i<=m;i++) { k = order[i]
      print k, pk[k] ? "yes" : "no", ik[k] ? "yes" : "no", ik[k] ? "yes" : "no", n[k] counts(k), nd[k] ? sprintf("%.3g", sd[k] / nd[k]) : "NA" }
    split("imoto_table1 thesis_table4_1 thesis_table4_2 thesis_table4_3 thesis_table4_4 thesis_table4_5 thesis_table4_6 thesis_table4_7", all, " ")
    for (b = 1; b <= 2; b++) { bd = b == 1 ? "printed" : "identified"
      for (i=1; i in all; i++) if (!((bd, all[i]) in B)) {
        # The table'"'"'s rates, as the printed board counts them (Table 4.4'"'"'s file lists each
        # weight once per reading of h); else the published file'"'"'s rows.
        np = npub[all[i]]
        if (np == "") { f = all[i] == "imoto_table1" ? pub "/imoto_table1.tsv" : pub "/" all[i] "_long.tsv"
          np = -1; while ((getline line < f) > 0) if (line !~ /^#/) np++
          close(f) }
        T[bd, 7] += np }
      tot = 0; s = ""; for (j = 1; j <= ncat; j++) { tot += T[bd, j]; s = s OFS (T[bd, j] + 0) }
      print "total", "as " bd, "document", b == 1 ? "yes" : "no", b == 2 ? "yes" : "no", b == 2 ? "yes" : "no", tot s, "NA" } }' pub="$pub" "$out" > "$score.tmp" < <(provenance)
mv "$score.tmp" "$score"
