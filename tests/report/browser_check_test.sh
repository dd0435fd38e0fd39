#!/usr/bin/env bash
# make test's check of the browser check (tests/report/browser_check.sh): a fixture page with
# a formula, a drawn figure, a figure whose text prints at 9 pt, superscripts and a wide table
# of long numbers and hyphenated words under the report's own CSS must pass at the A4
# printable width; a page with a formula pandoc cannot convert, a blank figure, a figure whose
# text prints below 8 pt, a table forced wider than the page, a cell whose number wraps, and
# a raw caret and a bare nan in the text, plain-text math, a raw identifier and a 15-digit number in
# table cells, and a superscript below 6 pt must fail, naming each.  (make report runs the check
# on the report itself.)
# usage: browser_check_test.sh SOURCE_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
for page in ok bad; do
  (cd "$fx" && pandoc --from markdown --to html5 --standalone --mathml --self-contained \
     --metadata title="$page" --css "$src/paper/style.css" "$page.md" -o "$tmp/$page.html" 2>/dev/null) ||
    { echo "FAIL: pandoc could not build the $page fixture"; exit 1; }
done
fail=0
if ! bash "$src/tests/report/browser_check.sh" "$tmp/ok.html"; then
  echo "FAIL: the good page was rejected"; fail=1
fi
out=$(bash "$src/tests/report/browser_check.sh" "$tmp/bad.html" 2>&1); rc=$?
printf '%s\n' "$out"
[ $rc -eq 1 ] || { echo "FAIL: the bad page gave exit $rc, expected 1"; fail=1; }
for kind in "FIGURE draws nothing" "TABLE wider than the page" "FORMULA not converted" \
    "SMALL TEXT in figure" "TABLE CELL splits \"0.000123456789012345\"" "RAW TEXT \"2^-" "RAW TEXT \" nan " "RAW MATH \"rho\"" "RAW MATH \"V_i\"" "RAW IDENTIFIER \"piecewise_cubic_polynomial\"" \
    "SMALL SCRIPT in figure" "LONG NUMBER \"0.000123456789012345\""; do
  printf '%s\n' "$out" | grep -q "$kind" || { echo "FAIL: the bad page's '$kind' was not reported"; fail=1; }
done
[ $fail -eq 0 ] && echo "browser check: good page passes, bad page rejected on every count"
exit $fail
