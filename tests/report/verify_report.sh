#!/bin/sh
# verify_report.sh — before pandoc runs: every figure and data table that paper/*.md
# references must exist, and every figure must be a non-empty SVG.  Prints one line per
# problem and exits 1, so a missing plot fails `make report` with a clear message instead
# of surfacing as a broken image.
#   usage: verify_report.sh [PAPER_DIR [DATA_DIR [ROOT]]]
#   PAPER_DIR  the report sources (default paper), files NN-*.md
#   DATA_DIR   where ```{.tsv file="x.tsv"}``` blocks read from (default data/quick)
#   ROOT       the directory image paths are relative to (default .)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
paper=${1:-paper}
data=${2:-data/quick}
root=${3:-.}
status=0
problem() { echo "verify-report: error: $*" >&2; status=1; }

set -- "$paper"/[0-9][0-9]-*.md
[ -e "$1" ] || { echo "verify-report: error: no report sources $paper/NN-*.md" >&2; exit 1; }

for md in "$@"; do
  # Images: ![...](path) — the target may follow a caption spread over several lines.
  for img in $(tr '\n' ' ' < "$md" | grep -o '\](figures/[^) ]*)' | sed 's/^](//; s/)$//'); do
    f="$root/$img"
    if [ ! -f "$f" ]; then problem "$md: figure missing: $img"; continue; fi
    if [ ! -s "$f" ]; then problem "$md: figure empty: $img"; continue; fi
    case "$img" in
      *.svg) grep -q '<svg' "$f" || problem "$md: figure is not an SVG: $img"
             grep -q '<path\|<polyline\|<circle\|<text' "$f" || problem "$md: SVG draws nothing: $img" ;;
    esac
  done
  # Tables: ```{.tsv file="x.tsv" ...}
  for tsv in $(grep -o '{\.tsv[^}]*file="[^"]*"' "$md" | sed 's/.*file="//; s/"$//'); do
    case "$tsv" in /*) f="$tsv" ;; *) f="$data/$tsv" ;; esac
    if [ ! -f "$f" ]; then problem "$md: data table missing: $f"; continue; fi
    grep -v '^#' "$f" | head -n 1 | grep -q . || problem "$md: data table has no header row: $f"
  done
done
[ $status -eq 0 ] && echo "verify-report: $# sources, every referenced figure and table present"
exit $status
