#!/usr/bin/env bash
# make test's check of the report's summary table on fixtures (tests/report/fixture/tables):
#   gpm verdicts  a figure drawn from a table's rows joins that table's row (before or after it),
#                 neighbouring illustrations of one document share a row, a rate table's evidence
#                 names only the verdicts that occur on each board, and a figure drawn from a
#                 table that has no rates row is refused (exit 2, one line).
# (The same rules on tables in memory: tests/unit/test_page_verdicts.cpp; the reasons collapsed
# per mechanism are gpm store-rates' (checked_reasons.hpp): tests/unit/test_checked_reasons.cpp.)
# usage: report_tables_test.sh SOURCE_DIR BUILD_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
gpm=${2:?usage: report_tables_test.sh SOURCE_DIR BUILD_DIR}/gpm
fx=$fx/tables
fail=0
expect() {  # expect FILE LINE: the file holds the line exactly
  grep -qxF "$2" "$1" || { echo "FAIL: $(basename "$1") lacks the line: $2"; fail=1; }
}
"$gpm" verdicts --items "$fx/items.tsv" --score "$fx/score.tsv" --data "$tmp" --out "$tmp/verdicts.tsv" ||
  { echo "FAIL: gpm verdicts rejected the fixture"; exit 1; }
tab=$(printf '\t')
expect "$tmp/verdicts.tsv" "Doc${tab}Fig. 1, Fig. 2${tab}particles; cells${tab}reproduced qualitatively${tab}illustrations drawn from the same definitions (no number to compare)${tab}ch"
expect "$tmp/verdicts.tsv" "Doc${tab}Table 1, Fig. 3${tab}rates${tab}partial${tab}both boards: 2 agree, 1 unexplained of 3${tab}ch"
expect "$tmp/verdicts.tsv" "Doc${tab}Table 2, Fig. 4${tab}rates${tab}reproduced${tab}identified: 4 agree of 4; printed: 4 unexplained of 4${tab}ch"
rows=$(grep -vc '^#' "$tmp/verdicts.tsv")
[ "$rows" = 4 ] || { echo "FAIL: verdicts.tsv has $rows lines, expected a header and 3 rows"; fail=1; }
"$gpm" verdicts --items "$fx/items_orphan.tsv" --score "$fx/score.tsv" --data "$tmp" --out "$tmp/orphan.tsv" 2> "$tmp/err"
rc=$?
if [ $rc -eq 0 ]; then
  echo "FAIL: a figure drawn from a table without a rates row was accepted"; fail=1
else
  [ $rc -eq 2 ] || { echo "FAIL: the orphan figure gave exit $rc, not 2"; fail=1; }
  grep -q "no rates row" "$tmp/err" || { echo "FAIL: the orphan figure's message is missing"; fail=1; }
  [ ! -e "$tmp/orphan.tsv" ] || { echo "FAIL: the refused run wrote its output"; fail=1; }
fi
[ $fail -eq 0 ] && echo "report tables: verdicts merged as specified"
exit $fail
