#!/usr/bin/env bash
# The reasons of checked_reasons.tsv collapsed to one row per mechanism: the reason's text
# up to its first ':' or ';' names the mechanism (what follows carries one table's numbers),
# and the row lists every (table, setting) it was checked on, with how many rows passed the
# check (naming them where only some did) and how many of those restore the published rate.
# usage: reasons_by_mechanism.sh CHECKED_REASONS OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
in=${1:-} out=${2:-}
[ -f "$in" ] && [ -n "$out" ] || { echo "reasons_by_mechanism: usage: reasons_by_mechanism.sh CHECKED_REASONS OUT (no file '$in')" >&2; exit 2; }
{
  echo "# program = tables/reasons_by_mechanism.sh"
  echo "# sources = $in"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'mechanism\trows\tchecked\tpassed\trestores\n'
  awk -F'\t' '
    /^#/ { next }
    !h++ { for (i = 1; i <= NF; i++) c[$i] = i
           split("table slice key reason check restores", need, " ")
           for (k in need) if (!(need[k] in c)) { print "reasons_by_mechanism: no column " need[k] > "/dev/stderr"; bad = 1; exit 2 }
           next }
    { mech = $c["reason"]; sub(/[:;].*/, "", mech)
      if (!(mech in seen)) { seen[mech] = 1; order[++nm] = mech }
      g = mech SUBSEP $c["table"] " " $c["slice"]
      if (!(g in rows)) { rows[g] = 1; groups[mech] = groups[mech] SUBSEP $c["table"] " " $c["slice"] }
      n[g]++; total[mech]++
      if ($c["check"] == "pass") { p[g]++; passed[mech]++; keys[g] = keys[g] (keys[g] == "" ? "" : ", ") $c["key"] }
      if ($c["restores"] == "yes") restores[mech]++ }
    END {
      if (bad) exit 2
      for (i = 1; i <= nm; i++) {
        mech = order[i]; k = split(substr(groups[mech], 2), ts, SUBSEP); list = ""
        for (j = 1; j <= k; j++) {
          g = mech SUBSEP ts[j]
          detail = (p[g] + 0 == 0 ? "none pass" : (p[g] == n[g] ? "all pass" : p[g] " pass (" keys[g] ")"))
          list = list (list == "" ? "" : "; ") ts[j] ": " n[g] (n[g] == 1 ? " row, " : " rows, ") detail }
        printf "%s\t%s\t%d\t%d\t%d\n", mech, list, total[mech], passed[mech], restores[mech] } }' "$in"
} > "$out.tmp"
mv "$out.tmp" "$out"
