#!/usr/bin/env bash
# make test's sampled recomputation of the store's finer units (issue 42).  The coarse check
# (verify_store.sh) recomputes only each file's cheapest levels, so an edited and re-sealed
# row at a rate level would pass it: a seal is a tripwire for accidents, anyone can recompute
# it.  This check recomputes, besides, a sample of the finer units — a unit is one level of
# a store file (of a heat file: one level and weight, its θ together) — and fails on any
# difference (--verify: numbers to 1e-9 relative).
#
# Which units: every unit above the file's coarse levels whose stored run took at most
# MAX_UNIT_S (the sum of its rows' distinct time columns, as measured when it was computed,
# on the machine its made_on names) is a candidate; candidates are ordered by a hash of the
# revision (git HEAD, or SAMPLE_SEED) and the unit, and taken in that order while their
# wall time stays within BUDGET_S (a unit started is finished).  Successive commits so draw different samples, and
# over enough of them every cheap unit is recomputed.  The sample and its coverage are printed.
#
# usage: verify_sample.sh BUILD_DIR STORE_DIR [BUDGET_S [MAX_UNIT_S]]   (defaults 60, 10)
#   SAMPLE_SEED=text  draw the sample from this text instead of the revision;
#   SAMPLE_UNITS="file:level[:weight] …"  recompute exactly these units (a test's choice).
export LC_ALL=C
set -u
usage="usage: verify_sample.sh BUILD_DIR STORE_DIR [BUDGET_S [MAX_UNIT_S]]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
build=$1 store=$2 budget=${3:-60} max_unit=${4:-10}
[ -x "$build/gpm" ] && [ -d "$store" ] || { echo "$usage" >&2; exit 2; }
seed=${SAMPLE_SEED:-$(git -C "$(dirname "$0")" rev-parse HEAD 2>/dev/null || echo none)}
# (An empty cell is written as "-": read would merge two tabs.)
listing=$("$build/gpm" study --store-rows) || { echo "verify_sample.sh: gpm study --store-rows failed" >&2; exit 2; }

# Every candidate: file, program, args, level, weight ("-": the whole level), predicted s,
# and of a heat unit the θ its rows hold ("-": all).
candidates() {
  while IFS=$'\t' read -r _study file program args _census coarse _slice; do
    [ -f "$store/$file.tsv" ] || continue  # (args stay "-" when empty: read merges two tabs)
    awk -F'\t' -v file="$file" -v program="$program" -v args="$args" -v coarse="${coarse#--levels }" -v heat=$([ "$program" = thesis_heat ] && echo 1 || echo 0) '
      BEGIN { n = split(coarse, c, ","); for (i = 1; i <= n; i++) low[c[i]] = 1 }
      /^#/ { next }
      !h++ { for (i = 1; i <= NF; i++) col[$i] = i; t = ("seconds" in col) ? col["seconds"] : col["time_s"]; next }
      ($col["level"] in low) { next }
      { u = $col["level"] "\t" (heat ? $col["weight"] : "-")
        if (!((u, $t) in seen)) { seen[u, $t] = 1; cost[u] += $t }
        if (heat && !((u, $col["theta"]) in th)) { th[u, $col["theta"]] = 1; thetas[u] = thetas[u] (thetas[u] == "" ? "" : ",") $col["theta"] } }
      END { for (u in cost) printf "%s\t%s\t%s\t%s\t%.3f\t%s\n", file, program, args, u, cost[u], heat ? thetas[u] : "-" }' "$store/$file.tsv"
  done <<<"$listing"
}
all=$(candidates)
total=$(grep -c . <<<"$all")
if [ -n "${SAMPLE_UNITS:-}" ]; then
  chosen=$(for u in $SAMPLE_UNITS; do
    IFS=: read -r f l w <<<"$u"
    awk -F'\t' -v f="$f" -v l="$l" -v w="${w:--}" '$1 == f && $4 == l && $5 == w' <<<"$all"
  done)
  [ -n "$chosen" ] || { echo "verify_sample.sh: no stored unit matches SAMPLE_UNITS='$SAMPLE_UNITS'" >&2; exit 2; }
else
  # The candidates in the revision's order; the loop below takes them while time is left.
  cheap=$(awk -F'\t' -v m="$max_unit" '$6 <= m' <<<"$all")
  chosen=$(while IFS= read -r line; do
      [ -n "$line" ] || continue
      printf '%s\t%s\n' "$(printf '%s\t%s' "$seed" "$line" | cut -f1,2,5,6 | md5sum | cut -c1-12)" "$line"
    done <<<"$cheap" | sort | cut -f2-)
fi
ncheap=$(awk -F'\t' -v m="$max_unit" '$6 <= m' <<<"$all" | grep -c .)
echo "sample of ${seed:0:12}: candidates $ncheap units (stored time <= ${max_unit} s each) of the $total above the coarse levels; recomputed in the sample's order until ${budget} s have passed"
failed=0 start=$SECONDS n=0
while IFS=$'\t' read -r file program args level weight cost thetas; do
  [ -n "$file" ] || continue
  [ -z "${SAMPLE_UNITS:-}" ] && [ $((SECONDS - start)) -ge "$budget" ] && break
  n=$((n + 1))
  [ "$args" = - ] && args=""
  sel=(--levels "$level")
  [ "$weight" != - ] && sel+=(--weights "$weight")
  [ "$thetas" != - ] && sel+=(--thetas "$thetas")  # the θ the file holds (some units hold θ = 0 only)
  t0=$SECONDS
  # shellcheck disable=SC2086  # the registry's arguments are words
  out=$("$build/$program" $args "${sel[@]}" --profile paper --out "$store/$file.tsv" --verify 2>&1)
  rc=$?
  summary=$(grep -m1 '^\[store\] verify' <<<"$out" | sed 's/.*max relative/max relative/')
  printf '  %-44s level %-3s %-30s stored %6.1f s, now %3d s: %s\n' "$file" "$level" "$weight" "$cost" $((SECONDS - t0)) "${summary:-exit $rc}"
  if [ $rc -ne 0 ]; then failed=$((failed + 1)); grep '\[store\]   differs\|error' <<<"$out" | head -3 | sed 's/^/     /'; fi
done <<<"$chosen"
echo "sampled check: $n units recomputed in $((SECONDS - start)) s, $failed differ"
[ $failed -eq 0 ]
