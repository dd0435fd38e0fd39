#!/usr/bin/env bash
# make tables (tables/reproduced_tables.sh) on the committed store: one TSV and one Markdown
# file per published table, each row with its published rate and ours under both boards, and
# as many rows as the store's document rates of that table on the identified board; a rates
# file without a needed column is refused naming it, nothing written.
# usage: tables_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: tables_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
src=$(cd "${2:?usage: tables_test.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
fail=0
(cd "$src" && "$build/gpm" store-rates --store results/paper --published tables/published --out "$t/r.tsv") \
  > /dev/null 2>&1 || { echo "FAIL: gpm store-rates"; exit 1; }
bash "$src/tables/reproduced_tables.sh" "$t/r.tsv" "$t/out" > "$t/log" 2>&1 || { echo "FAIL:"; cat "$t/log"; exit 1; }
tables=$(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["setup"] == "document" && $c["identified"] == "yes" { n[$c["table"]]++ }
  END { for (k in n) print k, n[k] }' "$t/r.tsv" | sort)
[ -n "$tables" ] || { echo "FAIL: no document rate in the store's rates"; exit 1; }
while read -r table n; do
  f=$t/out/$table.tsv
  [ -f "$f" ] && [ -f "$t/out/$table.md" ] || { echo "FAIL: $table: no TSV or Markdown written"; fail=1; continue; }
  got=$(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["published"] != "" && $c["ours_identified"] != "" && $c["verdict_identified"] != "" && $c["ours_printed"] != "" { n++ }
    END { print n + 0 }' "$f")
  [ "$got" = "$n" ] || { echo "FAIL: $table: $got complete rows, the store has $n rates"; fail=1; }
  grep -q "^## $table" "$t/out/$table.md" || { echo "FAIL: $table.md has no title"; fail=1; }
done <<<"$tables"
# A rates file without the verdict column: refused, naming it; nothing written.
awk -F'\t' -v OFS='\t' '/^#/ { print; next } { NF = NF - 1; print }' "$t/r.tsv" | cut -f1-10 > "$t/bad.tsv"
if bash "$src/tables/reproduced_tables.sh" "$t/bad.tsv" "$t/out2" > "$t/log" 2>&1; then
  echo "FAIL: a rates file without needed columns was accepted"; fail=1
elif ! grep -q "has no column" "$t/log" || [ -n "$(ls -A "$t/out2" 2>/dev/null)" ]; then
  echo "FAIL: the refusal does not name the column, or left files:"; cat "$t/log"; ls -A "$t/out2"; fail=1
fi
[ $fail -eq 0 ] && echo "make tables: $(wc -l <<<"$tables") tables, each TSV and Markdown complete"
exit $fail
