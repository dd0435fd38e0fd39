#!/usr/bin/env bash
# make test's check of tests/report/page_fill.py: Chromium prints two fixture pages to PDF; a
# chapter whose short last page is followed by the next chapter passes, a page left mostly
# blank by a break inside a chapter fails with its page number (and passes under --allow 1);
# a file that is not a PDF is a usage error.
# usage: page_fill_test.sh SOURCE_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
chrome=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chrome" ] || { echo "FAIL: chromium not installed (make deps installs it)"; exit 1; }
for page in page_ends_chapter page_ends_early; do
  "$chrome" --headless --no-sandbox --disable-gpu --no-pdf-header-footer \
    --print-to-pdf="$tmp/$page.pdf" "file://$fx/$page.html" 2>/dev/null ||
    { echo "FAIL: chromium could not print $page"; exit 1; }
done
fail=0
python3 "$src/tests/report/page_fill.py" "$tmp/page_ends_chapter.pdf" ||
  { echo "FAIL: a chapter's short last page was rejected"; fail=1; }
out=$(python3 "$src/tests/report/page_fill.py" "$tmp/page_ends_early.pdf"); rc=$?
printf '%s\n' "$out"
[ $rc -eq 1 ] && printf '%s\n' "$out" | grep -q "^BLANK PAGE 1:" ||
  { echo "FAIL: the page left blank inside a chapter was not reported (exit $rc)"; fail=1; }
python3 "$src/tests/report/page_fill.py" --allow 1 "$tmp/page_ends_early.pdf" >/dev/null ||
  { echo "FAIL: --allow 1 rejected a report with one such page"; fail=1; }
echo "not a pdf" > "$tmp/x.pdf"
python3 "$src/tests/report/page_fill.py" "$tmp/x.pdf" 2>/dev/null; rc=$?
[ $rc -eq 2 ] || { echo "FAIL: a file that is not a PDF gave exit $rc, expected 2"; fail=1; }
[ $fail -eq 0 ] && echo "page fill: a chapter end passes, a page blank inside a chapter fails, a non-PDF is refused"
exit $fail
