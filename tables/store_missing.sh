#!/usr/bin/env bash
# What the result store still owes: per paper-profile study of the plan, the levels its store
# file holds, the levels it lacks, and the predicted wall time of the missing ones on THIS
# machine (the plan's on-the-spot calibration, plan_paper_summary.tsv).  Levels the catalog
# trims from the paper profile (plan summary: trimmed = yes) are not owed: they are listed
# apart with what they would cost.  Nothing is run.
# usage: store_missing.sh STORE_DIR PLAN_SUMMARY OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
store=$1 plan=$2 out=$3
cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
{
  echo "# program = tables/store_missing.sh"
  echo "# store = $store"
  echo "# plan = $plan"
  echo "# machine = $cpu, $(nproc) cores (the plan's calibration ran here)"
  echo "# calibration_load = $(sed -n 's/^# calibration_load_before = //p' "${plan/_summary.tsv/.tsv}" "$plan" 2>/dev/null | head -1) (load average when the plan calibrated: above the 2 cores, the predictions are slower than an idle run)"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'study\tstore_file\tlevels_stored\tlevels_missing\tpredicted_missing_h\tlevels_trimmed\ttrimmed_h\n'
  awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
    $c["level"] != "all" && ("trimmed" in c) && $c["trimmed"] == "yes" {
      printf "X\t%s\t%s\t%.17g\n", $c["study"], $c["level"], $c["time_s"]; next }
    $c["level"] != "all" { t[$c["study"], $c["level"]] += $c["time_s"]; lv[$c["study"]] = lv[$c["study"]] " " $c["level"]
      if (!($c["study"] in seen)) { seen[$c["study"]] = 1; order[++n] = $c["study"] } }
    END { for (i = 1; i <= n; i++) { s = order[i]; printf "%s\t%s\n", s, lv[s]
            split(lv[s], L, " "); for (j in L) printf "%s\t%s\t%.17g\n", "T", s SUBSEP L[j], t[s, L[j]] } }' "$plan" > "$plan.levels.tmp"
  grep -v '^[TX]	' "$plan.levels.tmp" | while IFS=$'\t' read -r study levels; do
    f=$store/$study.tsv
    have=""
    if [ -f "$f" ]; then
      have=$(awk -F'\t' '/^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next } ("level" in c) { print $c["level"] }' "$f" | sort -un | paste -sd, -)
    fi
    awk -F'\t' -v s="$study" -v have=",$have," -v f="$(basename "$f")" -v ex="$([ -f "$f" ] && echo yes || echo no)" '
      $1 == "T" { split($2, k, SUBSEP); if (k[1] != s) next
        if (index(have, "," k[2] ",") == 0) { m[k[2] + 0] = 1; tm += $3 } }
      $1 == "X" && $2 == s { x[$3 + 0] = 1; tx += $4 }
      END { for (l = 0; l <= 20; l++) { if (l in m) miss = miss (miss == "" ? "" : ",") l
                                        if (l in x) trim = trim (trim == "" ? "" : ",") l }
            printf "%s\t%s\t%s\t%s\t%.2f\t%s\t%.2f\n", s, ex == "yes" ? f : "(none)", substr(have, 2, length(have) - 2) == "" ? "-" : substr(have, 2, length(have) - 2), miss == "" ? "-" : miss, tm / 3600, trim == "" ? "-" : trim, tx / 3600 }' "$plan.levels.tmp"
  done
  rm -f "$plan.levels.tmp"
} > "$out.tmp"
mv "$out.tmp" "$out"
