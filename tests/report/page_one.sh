#!/usr/bin/env bash
# The printed paper's first page holds the bottom line (issue 60): pdftotext of page 1 must show
# the paragraph "Bottom line." with its five numbered sentences (1)-(5), and the verdict
# table's legend after it — what a reader who opens the PDF and stops there takes away.
# Exit 0 when it does, 1 (naming what is missing) when not, 2 on a usage error.
# usage: page_one.sh REPORT.pdf
export LC_ALL=C.UTF-8
pdf=${1:-}
[ -f "$pdf" ] || { echo "page_one: no file '$pdf'" >&2; exit 2; }
command -v pdftotext >/dev/null || { echo "page_one: pdftotext not installed (make deps installs poppler-utils)" >&2; exit 2; }
text=$(pdftotext -f 1 -l 1 "$pdf" - | tr '\n' ' ')
missing=""
for want in "Bottom line." "(1)" "(2)" "(3)" "(4)" "(5)" "Verdict per item"; do
  case $text in *"$want"*) ;; *) missing="$missing '$want'" ;; esac
done
if [ -n "$missing" ]; then
  echo "page_one: page 1 of $pdf lacks$missing"
  exit 1
fi
echo "page_one: page 1 of $pdf holds the bottom line, its five sentences and the verdict table"
