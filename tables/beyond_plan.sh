#!/usr/bin/env bash
# The units past the documents (tables/beyond.tsv: issue 40), each priced by the plan on THIS
# machine and counted in the store.  Per row: the plan of the row's study at its level
# (`plan --study STUDY --levels LEVEL`, calibrated by CALIBRATION, the make run's plan) summed
# over the units of the row's part (time, including the Laplacian's set-up) with the largest
# peak memory; and the row's store file read by its own program in --census mode at that
# level (the registry's arguments), so a reader sees what is stored, what is not, and what the
# rest would cost.  A file the census cannot read (locked by a run writing it) says so.
# Nothing is computed.
# usage: beyond_plan.sh BUILD_DIR STORE_DIR CALIBRATION OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: beyond_plan.sh BUILD_DIR STORE_DIR CALIBRATION OUT" >&2; exit 2; }
build=$1 store=$2 calibration=$3 out=$4
here=$(dirname "$0")
[ -f "$calibration" ] || { echo "beyond_plan.sh: no calibration file '$calibration' (the make run's plan)" >&2; exit 2; }
# shellcheck source=tables/census_lib.sh
. "$here/census_lib.sh"
listing=$("$build/gpm" study --store-rows)
work=$(mktemp -d)
trap 'rm -rf "$work" "$out.tmp"' EXIT
rows=$work/rows
: > "$rows"
while IFS=$'\t' read -r file level plan_study variant census_match why; do
  case $file in \#*|store_file) continue ;; esac
  # The registry's study, program and arguments of the store file.
  entry=$(awk -F'\t' -v f="$file" '$2 == f' <<<"$listing")
  [ -n "$entry" ] || { echo "beyond_plan.sh: '$file' (tables/beyond.tsv) is no registry store file" >&2; exit 2; }
  IFS=$'\t' read -r study _ program args _ <<<"$entry"
  [ "$args" = - ] && args=""
  # The plan of the study at the level, once per (study, level).
  plan=$work/plan_${study}_$level.tsv
  [ -f "$plan" ] || "$build/plan" --study "$study" --levels "$level" --calibration "$calibration" --out "$plan" --quiet
  priced=$(awk -F'\t' -v s="$plan_study" -v v="$variant" -v k="$level" '
    /^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["study"] == s && $c["level"] == k && $c["variant"] ~ v {
      t += $c["time_s"]; if ($c["peak_mib"] > m) m = $c["peak_mib"]; if ($c["recorded"] == "yes") n++ }
    END { printf "%d\t%.2f\t%.2f", n, t / 3600, m / 1024 }' "$plan")
  # The store's count: the census of the file at the level, the row's units among its missing.
  f=$store/$file.tsv
  if [ ! -f "$f" ]; then
    state="not in the store"; missing=${priced%%$'\t'*}
  else
    census_read "$build" "$program" "$args --levels $level" "$f"
    if [ -n "$census_line" ]; then
      missing=$(awk -v p="$census_match" 'NF && $0 ~ p { n++ } END { print n + 0 }' <<<"$census_missing")
      state=read
    else
      missing=-; state=$census_problem
    fi
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$file" "$level" "$plan_study" "$priced" "$missing" "$state" "$why" >> "$rows"
done < "$here/beyond.tsv"
{
  echo "# program = tables/beyond_plan.sh"
  echo "# list = tables/beyond.tsv (the units past the documents issue 40 asks for)"
  echo "# store = $store"
  echo "# calibration = $calibration (the plan's calibration of this run)"
  echo "# machine = $(machine_line), $(awk '/MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo) (the plan's calibration ran here)"
  echo "# calibration_load = $(sed -n 's/^# calibration_load_before = //p' "$calibration" | head -1) (load average when the plan calibrated: above the cores, the predictions are slower than an idle run)"
  echo "# plan_h = predicted hours for the row's units on this machine, idle, every thread (Laplacian set-up included; the theta of one weight share one Krylov subspace); peak_gib = the largest unit's predicted peak memory"
  echo "# stored = units of the row the store holds (its census at the level); missing = units the census names as missing"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'store_file\tlevel\tpart\tunits\tplan_h\tpeak_gib\tstored\tmissing\tmissing_h\tcensus\twhy\n'
  awk -F'\t' -v OFS='\t' '{
      units = $4; miss = $7
      stored = (miss == "-") ? "-" : units - miss
      mh = (miss == "-" || units == 0) ? "-" : sprintf("%.2f", $5 * miss / units)
      print $1 ".tsv", $2, $3, units, $5, $6, stored, miss, mh, $8, $9 }' "$rows"
} > "$out.tmp"
mv "$out.tmp" "$out"
