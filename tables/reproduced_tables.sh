#!/usr/bin/env bash
# make tables: every reproduced table of the three documents, published beside ours at paper
# scale, one TSV and one Markdown file per table in OUT_DIR (issue 60).  Read from the judging
# pass's store_rates.tsv (gpm store-rates over the committed store, whatever the profile): per
# published rate, ours under the set-up as printed and under the identified one, each with its
# verdict, the seed band and the least-squares slope past the transition.  Columns by name.
#
# usage: reproduced_tables.sh STORE_RATES.tsv OUT_DIR
export LC_ALL=C
set -euo pipefail
rates=${1:?usage: reproduced_tables.sh STORE_RATES.tsv OUT_DIR}
out=${2:?usage: reproduced_tables.sh STORE_RATES.tsv OUT_DIR}
[ -f "$rates" ] || { echo "reproduced_tables.sh: no file $rates" >&2; exit 2; }
mkdir -p "$out"
tmp=$(mktemp -d "$out/.tables.XXXXXX"); trap 'rm -rf "$tmp"' EXIT
revision=$(awk -F' = ' '$1 == "# git_revision" { print $2; exit }' "$rates")
# One TSV per table into tmp (written whole, then moved): rows in the store's order.
awk -F'\t' -v OFS='\t' -v dir="$tmp" -v src="$rates" -v rev="$revision" '
  /^#/ { next }
  !h++ { for (i = 1; i <= NF; i++) c[$i] = i
         split("table slice setup key published reproduced verdict printed identified verdict_identified seed_band lsq levels", need, " ")
         for (i in need) if (!(need[i] in c)) { printf "reproduced_tables.sh: %s has no column %s\n", src, need[i] > "/dev/stderr"; bad = 1; exit 2 }
         next }
  $c["setup"] != "document" { next }
  { t = $c["table"]; k = t SUBSEP $c["key"]
    if (!(k in seen)) { seen[k] = 1; order[++n] = k; if (!(t in tabs)) { tabs[t] = 1; tlist[++nt] = t } }
    pub[k] = $c["published"]
    if ($c["printed"] == "yes") { ps[k] = $c["slice"]; pr[k] = $c["reproduced"]; pv[k] = $c["verdict"]; pslice[t] = $c["slice"] }
    if ($c["identified"] == "yes") { is[k] = $c["slice"]; ir[k] = $c["reproduced"]; iv[k] = $c["verdict_identified"]
                                     band[k] = $c["seed_band"]; lsq[k] = $c["lsq"]; lv[k] = $c["levels"] } }
  function num(x) { return x ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ ? sprintf("%.2f", x) : x }
  END {
    if (bad) exit 2
    for (j = 1; j <= nt; j++) {
      t = tlist[j]; f = dir "/" t ".tsv"
      print "# table = " t > f
      print "# source = " src " (gpm store-rates: the committed paper-scale store, rates at the level pair of the documents)" > f
      print "# git_revision = " rev > f
      print "# columns = published rate; ours and verdict under the set-up as printed and as identified (readings named per row); seed band and least-squares slope past the transition of the identified reading" > f
      print "key", "published", "printed_reading", "ours_printed", "verdict_printed", "identified_reading", "ours_identified", "verdict_identified", "levels", "seed_band", "lsq_past_transition" > f
      for (i = 1; i <= n; i++) {
        k = order[i]; split(k, p, SUBSEP); if (p[1] != t) continue
        print p[2], pub[k], ps[k], num(pr[k]), pv[k], is[k], num(ir[k]), iv[k], lv[k], band[k], lsq[k] > f
      }
      close(f)
    } }' "$rates"
# Markdown beside each TSV: the same columns, a title naming the table.
for f in "$tmp"/*.tsv; do
  [ -e "$f" ] || { echo "reproduced_tables.sh: no document rate in $rates" >&2; exit 1; }
  awk -F'\t' '
    /^# table = / { printf "## %s: published against reproduced (paper scale)\n\n", substr($0, 11); next }
    /^# source = / { src = substr($0, 12); next }
    /^#/ { next }
    !h++ { line = "|"; sep = "|"; for (i = 1; i <= NF; i++) { line = line " " $i " |"; sep = sep "---|" }
           print line; print sep; next }
    { line = "|"; for (i = 1; i <= NF; i++) line = line " " ($i == "" ? "-" : $i) " |"; print line }
    END { printf "\nFrom %s.\n", src }' "$f" > "${f%.tsv}.md"
done
written=()
for f in "$tmp"/*.tsv "$tmp"/*.md; do
  mv "$f" "$out/$(basename "$f")"; written+=("$out/$(basename "$f")")
done
echo "make tables: wrote ${#written[@]} files (published beside ours, paper scale):"
printf '  %s\n' "${written[@]}"
