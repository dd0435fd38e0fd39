#!/usr/bin/env bash
# make test's check of tests/report/page_fill.py and print_pdf.py: Chromium prints fixture
# pages to PDF; a chapter whose last page is about 40 % full before the next chapter passes, a
# page left mostly blank by a break inside a chapter fails with its page number (and passes
# under --allow 1), a chapter's stub page (under a quarter full) fails even before a chapter,
# and print_pdf.py removes that stub by letting the next chapter follow on it; a file that is
# not a PDF is a usage error.
# usage: page_fill_test.sh SOURCE_DIR
. "$(dirname "$0")/fixture_env.sh"  # LC_ALL=C, src, fx, tmp
chrome=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chrome" ] || { echo "FAIL: chromium not installed (make deps installs it)"; exit 1; }
for page in page_ends_chapter page_ends_early page_stub_chapter; do
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
out=$(python3 "$src/tests/report/page_fill.py" "$tmp/page_stub_chapter.pdf"); rc=$?
printf '%s\n' "$out"
[ $rc -eq 1 ] && printf '%s\n' "$out" | grep -q "^BLANK PAGE 2: .*under a quarter" ||
  { echo "FAIL: a chapter's stub page before the next chapter was not reported (exit $rc)"; fail=1; }
cp "$fx/page_stub_chapter.html" "$tmp/stub.html"
out=$(python3 "$src/tests/report/print_pdf.py" "$tmp/stub.html" "$tmp/stub.pdf")
printf '%s\n' "$out" | grep -q "chapter 'second' follows on it" ||
  { echo "FAIL: print_pdf.py did not let the chapter after the stub follow on it"; fail=1; }
python3 "$src/tests/report/page_fill.py" "$tmp/stub.pdf" ||
  { echo "FAIL: the stub is still there after print_pdf.py"; fail=1; }
cmp -s "$fx/page_stub_chapter.html" "$tmp/stub.html" && [ -z "$(ls -A "$tmp" | grep '^\.print-')" ] ||
  { echo "FAIL: print_pdf.py changed the HTML or left its copy"; fail=1; }
echo "not a pdf" > "$tmp/x.pdf"
python3 "$src/tests/report/page_fill.py" "$tmp/x.pdf" 2>/dev/null; rc=$?
[ $rc -eq 2 ] || { echo "FAIL: a file that is not a PDF gave exit $rc, expected 2"; fail=1; }
[ $fail -eq 0 ] && echo "page fill: a chapter end passes, a page blank inside a chapter fails, a stub fails and the printer removes it, a non-PDF is refused"
exit $fail
