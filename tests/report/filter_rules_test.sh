#!/usr/bin/env bash
# make test's check of the report filter's rules (paper/tsv-tables.lua): a fixture page that
# reads its numbers from data (datum, row counts, counts), gives its nan cells a word, sets
# plain-text math and full doubles in cells as a reader reads them, and names only levels
# and files its data hold must build; each bad page must stop pandoc with its own message:
# a caption naming a level or a file the data lack, a nan cell without a word, counts that
# leave a category out, a datum with no row, a value the prose has no words for.  The same
# sources split into a paper and a supplement (long tables and appendices to the supplement).
# usage: filter_rules_test.sh SOURCE_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
fx=$fx/filter
build() {  # build PAGE: pandoc with the report's filter, in the fixture folder (its data, its figures)
  (cd "$fx" && pandoc --from markdown --to html5 --lua-filter "$src/paper/tsv-tables.lua" \
     --metadata datadir=data "$1.md" -o "$tmp/$1.html" 2>&1)
}
fail=0
out=$(build good) || { printf '%s\n' "$out"; echo "FAIL: the good page was rejected"; fail=1; }
grep -q "6 agree, 3 differ and 1 not computed" "$tmp/good.html" 2>/dev/null ||
  { echo "FAIL: the good page's counts are not '6 agree, 3 differ and 1 not computed'"; fail=1; }
grep -q "computed; 60 per" "$tmp/good.html" 2>/dev/null || { echo "FAIL: the good page's scaled datum is not 60"; fail=1; }
grep -q "1 printed board and 0 identified boards" "$tmp/good.html" 2>/dev/null ||
  { echo "FAIL: the good page's row counts (count=yes, one row and none) are not 1 and 0"; fail=1; }
grep -q "no solution" "$tmp/good.html" 2>/dev/null || { echo "FAIL: the good page's nan cell lost its word"; fail=1; }
# Plain-text math and full doubles in cells: r_c as r with a subscript c (Unicode has no
# subscript c), a 16-digit number to 6 significant digits.
grep -q "r<sub>c</sub>/Δx" "$tmp/good.html" 2>/dev/null || { echo "FAIL: the good page's r_c/dx is not r<sub>c</sub>/Δx"; fail=1; }
grep -q "L<sub>w</sub> of" "$tmp/good.html" 2>/dev/null || { echo "FAIL: the good page's L_w is not L<sub>w</sub>"; fail=1; }
grep -q ">0.00415872<" "$tmp/good.html" 2>/dev/null || { echo "FAIL: the good page's 0.004158723777973314 is not 0.00415872"; fail=1; }
# A table filter of several conditions, one with alternatives: every condition must hold.
sed -n '/kept board/,/<\/table>/p' "$tmp/good.html" 2>/dev/null | grep -q '>printed<' ||
  { echo "FAIL: filter board=printed|identified,rates=10 dropped the printed row"; fail=1; }
sed -n '/dropped board/,/<\/table>/p' "$tmp/good.html" 2>/dev/null | grep -q '>printed<' &&
  { echo "FAIL: filter board=printed,rates=9 kept the printed row (rates is 10)"; fail=1; }
while IFS='|' read -r page expect; do
  out=$(build "$page"); rc=$?
  if [ $rc -eq 0 ]; then echo "FAIL: $page was accepted"; fail=1
  elif ! printf '%s\n' "$out" | grep -q "$expect"; then
    printf '%s\n' "$out"; echo "FAIL: $page did not report '$expect'"; fail=1
  fi
done <<'CASES'
bad_caption_level|caption names level 2^-9
bad_caption_file|caption names errors_old.tsv
bad_nan|without a word saying what failed
bad_counts|a category is missing
bad_datum|no row of data/score.tsv
bad_map|has no words in the map
CASES
# The paper and its supplement: the long table leaves the paper for a pointer, the supplement
# holds it (numbered), the appendix and the provenance appendix; the short table stays; a
# section marked {.supplement} moves (a pointer stays) up to the next heading of its level.
split() {  # split PART: the split fixture as that part, its text without tags
  (cd "$fx" && pandoc --from markdown --to html5 --lua-filter "$src/paper/tsv-tables.lua" \
     --metadata datadir=data --metadata part="$1" split.md 2>&1) | sed 's/<[^>]*>//g' | tr -s ' \n' ' '
}
paper=$(split paper) supplement=$(split supplement) companion=$(split docs)
for want in "Table S1 (supplement, 30 rows): A long table of Uk." "A short table." "Figure 1. A main figure." \
            "Section S1 (supplement): A side section" "Main text." "Section C1 (companion): A quick section"; do
  case $paper in *"$want"*) ;; *) echo "FAIL: the paper lacks '$want'"; fail=1 ;; esac
done
# The paper counts a chapter's data files and points to the supplement, which lists them.
case $paper in *"Data of this chapter: "[0-9]*" file"*"supplement's last appendix"*) ;;
  *) echo "FAIL: the paper does not count its chapter's data files and point to the supplement"; fail=1 ;; esac
for unwanted in "Appendix A" "Appendix B" "Side text." "Data of this chapter: data/" "Companion text." "Quick text."; do
  case $paper in *"$unwanted"*) echo "FAIL: the paper holds '$unwanted'"; fail=1 ;; esac
done
for want in "Table S1. A long table of Uk." "Appendix A. Details" "Appendix B. Provenance" "Figure S1. A side figure." \
            "Section S1. A side section" "Side text."; do
  case $supplement in *"$want"*) ;; *) echo "FAIL: the supplement lacks '$want'"; fail=1 ;; esac
done
for unwanted in "A short table." "Main text." "Companion text." "A long companion table." "Quick text."; do
  case $supplement in *"$unwanted"*) echo "FAIL: the supplement holds '$unwanted'"; fail=1 ;; esac
done
# The companion (part docs): the chapters marked {.docs}, whole (its long table in place), and the
# sections marked {.docs} under their chapter's name; nothing of the paper's or the supplement's.
for want in "Companion text." "A long companion table." "Appendix. Provenance" "Companion to: A chapter" \
            "Section C1. A quick section" "Quick text."; do
  case $companion in *"$want"*) ;; *) echo "FAIL: the companion lacks '$want'"; fail=1 ;; esac
done
for unwanted in "Main text." "Side text." "Appendix A. Details" "Table S1"; do
  case $companion in *"$unwanted"*) echo "FAIL: the companion holds '$unwanted'"; fail=1 ;; esac
done
[ $fail -eq 0 ] && echo "filter rules: good page builds, each of the 6 bad pages stopped with its message, paper, supplement and companion split (long table, marked section, {.docs} chapter), table filters of several conditions, figures numbered per part"
exit $fail
