#!/usr/bin/env bash
# make test's check of tests/report/page_one.sh: Chromium prints a page one holding the bottom
# line with its five sentences and the verdict table (must pass), and one whose sentence (5) and
# table were pushed to page 2 (must fail, naming both).
# usage: page_one_test.sh SOURCE_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
chrome=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chrome" ] || { echo "FAIL: chromium not installed (make deps installs it)"; exit 1; }
line='<p><b>Bottom line.</b> (1) One. (2) Two. (3) Three. (4) Four.'
cat > "$tmp/good.html" <<HTML
<html><body>$line (5) Five.</p><table><caption>Verdict per item of the documents</caption><tr><td>x</td></tr></table></body></html>
HTML
cat > "$tmp/bad.html" <<HTML
<html><body>$line</p><div style="break-before: page">(5) Five.</div><table><caption>Verdict per item</caption><tr><td>x</td></tr></table></body></html>
HTML
for page in good bad; do
  "$chrome" --headless --no-sandbox --disable-gpu --no-pdf-header-footer \
    --print-to-pdf="$tmp/$page.pdf" "file://$tmp/$page.html" 2>/dev/null ||
    { echo "FAIL: chromium could not print $page"; exit 1; }
done
fail=0
bash "$src/tests/report/page_one.sh" "$tmp/good.pdf" || { echo "FAIL: the good page one was rejected"; fail=1; }
out=$(bash "$src/tests/report/page_one.sh" "$tmp/bad.pdf"); rc=$?
printf '%s\n' "$out"
[ $rc -eq 1 ] && printf '%s\n' "$out" | grep -q "'(5)' 'Verdict per item'" ||
  { echo "FAIL: the page one without sentence (5) and the table was not refused (exit $rc)"; fail=1; }
bash "$src/tests/report/page_one.sh" "$tmp/none.pdf" 2>/dev/null; [ $? -eq 2 ] || { echo "FAIL: a missing file is not a usage error"; fail=1; }
[ $fail -eq 0 ] && echo "page one check: the bottom line on page 1 passes, one pushed to page 2 fails"
exit $fail
