#!/usr/bin/env bash
# What the result store still owes, from the census itself: every store file of the study
# registry (`gpm study --store-files`) is read by its own program in --census mode, which
# names each unit of the file's census levels that the file lacks (the same count make test's
# store check fails on).  Each missing unit is priced by the plan's prediction for its study
# and level on THIS machine (PLAN_SUMMARY, the plan's on-the-spot calibration: time of the
# level over its units).  The levels the catalog trims from the paper profile (plan summary:
# trimmed = yes) are not owed: the study's first file lists them with what they would cost.
# A file the census cannot read (locked by a run writing it, unreadable) is listed with the
# reason.  Nothing is computed.
# usage: store_census.sh BUILD_DIR STORE_DIR PLAN_SUMMARY OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: store_census.sh BUILD_DIR STORE_DIR PLAN_SUMMARY OUT" >&2; exit 2; }
build=$1 store=$2 plan=$3 out=$4
# shellcheck source=tables/census_lib.sh
. "$(dirname "$0")/census_lib.sh"
listing=$("$build/gpm" study --store-rows)
rows=$(mktemp)
trap 'rm -f "$rows" "$out.tmp"' EXIT
# (gpm study --store-rows writes an empty cell "-": read would merge two tabs.)
while IFS=$'\t' read -r study file program args census _coarse _slice; do
  [ "$args" = - ] && args=""
  [ "$census" = - ] && census=""
  f=$store/$file.tsv
  if [ ! -f "$f" ]; then printf '%s\t%s\t0\tall\t-\tnot in the store\n' "$study" "$file" >> "$rows"; continue; fi
  census_read "$build" "$program" "$args $census" "$f"
  if [ -z "$census_line" ]; then
    printf '%s\t%s\t-\t-\t-\t%s\n' "$study" "$file" "$census_problem" >> "$rows"
    continue
  fi
  n=$(sed 's/.*: \([0-9]*\) rows, \([0-9]*\) units.*/\1 \2/' <<<"$census_line")
  levels=$(sed -n 's/.*level \([0-9]*\).*/\1/p' <<<"$census_missing" | sort -n |
           uniq -c | awk '{ printf "%s%s:%s", (NR > 1 ? "," : ""), $2, $1 }')
  printf '%s\t%s\t%s\t%s\t%s\tread\n' "$study" "$file" "${n% *}" "${n#* }" "${levels:--}" >> "$rows"
done <<<"$listing"
{
  echo "# program = tables/store_census.sh"
  echo "# store = $store"
  echo "# plan = $plan"
  echo "# census = each registry store file read by its program with --census (the units of its census levels it lacks)"
  echo "# machine = $(machine_line) (the plan's calibration ran here)"
  echo "# calibration_load = $(sed -n 's/^# calibration_load_before = //p' "${plan/_summary.tsv/.tsv}" "$plan" 2>/dev/null | head -1) (load average when the plan calibrated: above the 2 cores, the predictions are slower than an idle run)"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'study\tstore_file\trows\tunits_missing\tmissing_by_level\tpredicted_missing_h\tlevels_trimmed\ttrimmed_h\tcensus\n'
  awk -F'\t' -v OFS='\t' '
    FILENAME == ARGV[1] { if (/^#/) next; if (!h++) { for (i = 1; i <= NF; i++) c[$i] = i; next }
      if ($c["level"] == "all") next
      if (("trimmed" in c) && $c["trimmed"] == "yes") { tr[$1] = tr[$1] (tr[$1] == "" ? "" : ",") $c["level"]; th[$1] += $c["time_s"]; next }
      per[$1, $c["level"]] = $c["units"] > 0 ? $c["time_s"] / $c["units"] : 0; next }
    { t = 0; if ($5 != "-") { n = split($5, L, ","); for (j = 1; j <= n; j++) { split(L[j], kv, ":"); t += kv[2] * per[$1, kv[1]] } }
      first = !seen[$1]++
      print $1, $2 ".tsv", $3, $4, $5, sprintf("%.2f", t / 3600),
            first && ($1 in tr) ? tr[$1] : "-", first && ($1 in tr) ? sprintf("%.2f", th[$1] / 3600) : "-", $6 }' "$plan" "$rows"
} > "$out.tmp"
mv "$out.tmp" "$out"
