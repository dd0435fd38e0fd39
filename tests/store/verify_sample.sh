#!/usr/bin/env bash
# make test's sampled recomputation of the store's finer units (issue 42).  The coarse check
# (verify_store.sh) recomputes only each file's cheapest levels, so an edited and re-sealed
# row at a rate level would pass it: a seal is a tripwire for accidents, anyone can recompute
# it.  This check recomputes, besides, a sample of the finer units — a unit is one level of
# a store file (of a heat file: one level and weight, its θ together; of Table 4.4's, 4.1-4.3's
# and imoto's: one level and its key values, sub_key below) — and fails on any difference (--verify: numbers to 1e-9 relative; by a
# cheaper path at that path's tolerance, below).
#
# Which units (tests/store/sample_draw.py, issue 61 item 6): every unit above the file's
# coarse levels whose stored run took at most MAX_UNIT_S (the sum of its rows' distinct time
# columns, as measured when it was computed, on the machine its made_on names) has a known
# chance per run, cost-weighted so that a run's expected recomputation is BUDGET_S: cheap units
# often, expensive ones rarely, each sometimes.  The draw is a hash of the revision (git HEAD,
# or SAMPLE_SEED) and the unit, so successive commits draw independently.  Units above
# MAX_UNIT_S are never drawn here (one could outlast the suite): make verify-store-full
# recomputes them.  A run that passes 3 BUDGET_S stops and says how many drawn units it left.
#
# A unit dearer than that by its own path may be reached by a cheaper, independent one (issue
# 58 item 3, verify_store_full.sh --cheap): Table 4.4's plain-CG rows by the tau-preconditioned
# solver (compared at 1e-6; predicted: assembly plus solve x 15 / its CG iterations), a heat
# unit by the propagator with fewer products (compared at 1e-4 where a row's propagator is not
# its own; predicted: what verified.log measured for its level by that path, shared among the
# level's weights, else its stored time).  The draw prices each unit by the cheaper of the two.
#
# usage: verify_sample.sh BUILD_DIR STORE_DIR [BUDGET_S [MAX_UNIT_S]]   (defaults 60, 60)
#   SAMPLE_SEED=text  draw the sample from this text instead of the revision;
#   SAMPLE_UNITS="file:level[:weight[:cheap]] …"  recompute exactly these units (a test's choice;
#                      ":cheap": by its cheaper path, "-" for a weight if it has none);
#   SAMPLE_COVERAGE=N  recompute nothing: print the coverage per run and after N runs, expected
#                      from the chances and counted over N seeds.
export LC_ALL=C
set -u
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/../.." && pwd)/tables/census_lib.sh"
usage="usage: verify_sample.sh BUILD_DIR STORE_DIR [BUDGET_S [MAX_UNIT_S]]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
build=$1 store=$2 budget=${3:-60} max_unit=${4:-60}
[ -x "$build/gpm" ] && [ -d "$store" ] || { echo "$usage" >&2; exit 2; }
seed=${SAMPLE_SEED:-$(git -C "$(dirname "$0")" rev-parse HEAD 2>/dev/null || echo none)}
# (An empty cell is written as "-": read would merge two tabs.)
listing=$("$build/gpm" study --store-rows) || { echo "verify_sample.sh: gpm study --store-rows failed" >&2; exit 2; }

# Every candidate: file, program, args, level, weight ("-": the whole level), predicted s,
# of a heat unit the θ its rows hold ("-": all), then the cheaper path's options ("-": none)
# and its predicted s.
# The key columns besides the level that make one unit of a study whose units can be selected
# one by one (unit_key in census_lib.sh), empty for a whole level (a file whose arguments select
# with --only already, the studies that name their particle sets themselves, and the heat
# files, drawn by weight below).
sub_key() {
  [[ " $2 " == *" --only "* ]] && return
  [ "$1" = thesis_heat ] || unit_key "$1"
}
# The seconds verify_store_full.sh measured per (file, level) by a path other than the own one
# (its latest agreeing line of the whole level: a part's line, "--only PART" or "--weights
# PART", times one part),
# "file<TAB>level<TAB>seconds<TAB>path".
measured=$(awk -F'\t' 'NR > 1 && $9 == "agree" && $13 != "own" && line_part($13) == "-" { m[$2 "\t" $3] = $10 "\t" $13 }
  END { for (k in m) print k "\t" m[k] }
  '"$line_part_awk" "$store/verified.log" 2>/dev/null)
candidates() {
  while IFS=$'\t' read -r _study file program args census coarse _slice; do
    [ -f "$store/$file.tsv" ] || continue  # (args stay "-" when empty: read merges two tabs)
    # The census's options beyond its levels (a file holding some variants only, --only h15)
    # go along with the unit, and only the words after --levels are the coarse levels.
    [ "$census" = - ] && census=""
    extra=$(census_options "$census")
    [ -n "$extra" ] && { [ "$args" = - ] && args=$extra || args="$args $extra"; }
    coarse=$(awk '{ for (i = 1; i < NF; i++) if ($i == "--levels") print $(i + 1) }' <<<"$coarse")
    cheap=$(cheaper_path "$program" "$file" "$store/$file.tsv")  # as verify_store_full.sh --cheap
    { printf '%s\n' "$measured"; echo "==="; cat "$store/$file.tsv"; } |
    awk -F'\t' -v file="$file" -v program="$program" -v args="$args" -v coarse="$coarse" -v cheap="$cheap" -v heat=$([ "$program" = thesis_heat ] && echo 1 || echo 0) \
        -v subkey="$(sub_key "$program" "$args")" '
      BEGIN { n = split(coarse, c, ","); for (i = 1; i <= n; i++) low[c[i]] = 1; ns = split(subkey, sk, ",") }
      !body { if ($0 == "===") body = 1; else if ($1 == file && $4 == cheap) by_path[$2] = $3; next }
      /^#/ { next }
      !h++ { for (i = 1; i <= NF; i++) col[$i] = i; t = ("seconds" in col) ? col["seconds"] : col["time_s"]; next }
      ($col["level"] in low) { next }
      { part = ""; for (i = 1; i <= ns; i++) part = part (i > 1 ? "," : "") $col[sk[i]]
        u = $col["level"] "\t" (heat ? $col["weight"] : ns ? part : "-")
        if (!((u, $t) in seen)) { seen[u, $t] = 1; cost[u] += $t; fast[u] += (cheap == "-" ? $t : cheaper_s(col, t)) }
        if (!(($col["level"], u) in in_level)) { in_level[$col["level"], u] = 1; units[$col["level"]]++ }
        if (heat && !((u, $col["theta"]) in th)) { th[u, $col["theta"]] = 1; thetas[u] = thetas[u] (thetas[u] == "" ? "" : ",") $col["theta"] } }
      '"$cheaper_seconds_awk"'
      END { for (u in cost) { split(u, lw, "\t")
              if (lw[1] in by_path) fast[u] = by_path[lw[1]] / units[lw[1]]
              printf "%s\t%s\t%s\t%s\t%.3f\t%s\t%s\t%.3f\n", file, program, args, u, cost[u], heat ? thetas[u] : "-", cheap, fast[u] } }'
  done <<<"$listing"
}
all=$(candidates)
total=$(grep -c . <<<"$all")
if [ -n "${SAMPLE_UNITS:-}" ]; then
  chosen=$(for u in $SAMPLE_UNITS; do
    IFS=: read -r f l w how <<<"$u"
    awk -F'\t' -v OFS='\t' -v f="$f" -v l="$l" -v w="${w:--}" -v how="${how:-}" '
      $1 == f && $4 == l && $5 == w { p = how == "cheap" ? $8 : "-"; NF = 7; print $0, p }' <<<"$all"
  done)
  [ -n "$chosen" ] || { echo "verify_sample.sh: no stored unit matches SAMPLE_UNITS='$SAMPLE_UNITS'" >&2; exit 2; }
elif [ -n "${SAMPLE_COVERAGE:-}" ]; then
  python3 "$(dirname "$0")/sample_draw.py" --seed "$seed" --budget "$budget" --max-unit "$max_unit" \
    --coverage "$SAMPLE_COVERAGE" <<<"$all"
  exit
else
  log=$(mktemp); trap 'rm -f "$log"' EXIT
  chosen=$(python3 "$(dirname "$0")/sample_draw.py" --seed "$seed" --budget "$budget" --max-unit "$max_unit" \
    <<<"$all" 2>"$log") || { cat "$log" >&2; exit 2; }
  drew=$(cat "$log")
  echo "sample of ${seed:0:12} among the $total units above the coarse levels: $drew"
fi
failed=0 start=$SECONDS n=0
while IFS=$'\t' read -r file program args level weight cost thetas path; do
  [ -n "$file" ] || continue
  if [ -z "${SAMPLE_UNITS:-}" ] && [ $((SECONDS - start)) -ge $((3 * budget)) ]; then
    echo "sample cut at 3 x ${budget} s: $(($(grep -c . <<<"$chosen") - n)) drawn units not recomputed"; break
  fi
  n=$((n + 1))
  [ "$args" = - ] && args=""
  sel=(--levels "$level")
  # A heat unit is a level and weight; another study's a level and its key values (--only).
  [ "$weight" != - ] && if [ "$program" = thesis_heat ]; then sel+=(--weights "$weight"); else sel+=(--only "$weight"); fi
  [ "$thetas" != - ] && sel+=(--thetas "$thetas")  # the θ the file holds (some units hold θ = 0 only)
  [ "${path:--}" != - ] && read -ra more <<<"$path" && sel+=("${more[@]}")  # the cheaper path
  t0=$SECONDS
  # shellcheck disable=SC2086  # the registry's arguments are words
  out=$("$build/$program" $args "${sel[@]}" --profile paper --out "$store/$file.tsv" --verify 2>&1)
  rc=$?
  summary=$(grep -m1 '^\[store\] verify' <<<"$out" | sed 's/.*max relative/max relative/')
  printf '  %-44s level %-3s %-30s stored %6.1f s, now %3d s%s: %s\n' "$file" "$level" "$weight" "$cost" $((SECONDS - t0)) \
    "$([ "${path:--}" != - ] && echo " by $path")" "${summary:-exit $rc}"
  if [ $rc -ne 0 ]; then failed=$((failed + 1)); grep '\[store\]   differs\|error' <<<"$out" | head -3 | sed 's/^/     /'; fi
done <<<"$chosen"
echo "sampled check: $n units recomputed in $((SECONDS - start)) s, $failed differ"
[ $failed -eq 0 ]
