#!/usr/bin/env bash
# The [paper] tier, part of make test: every paper-scale rate in the committed result store
# (results/paper) against its published value, on both scoreboards of gpm store-rates (the
# reading as printed and the one the documents' fingerprint identifies; each of the 80
# published rates once per board).  The verdicts are computed from the stored rows
# exactly as the report computes them (gpm checked-reasons, gpm store-rates):
# agrees, non-convergence reproduced, inside the seed band, or differs with a checked reason.
# A rate that differs without a checked reason must be listed, with what is open about it, in
# tests/paper/known_unexplained.tsv — the package's open items, in one file.  The test fails
#   * on an unexplained rate that is not listed (a regression, or a new rate nobody looked at),
#   * on a listed rate that is no longer unexplained (the list must shrink when one is solved),
#   * if the store yields no document rate at all.
#
# usage: check_verdicts.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
build=$(cd "$1" && pwd)
cd "$2"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/gpm" checked-reasons --store results/paper --out "$tmp/checked.tsv"
"$build/gpm" store-rates --store results/paper --checked "$tmp/checked.tsv" --out "$tmp/rates.tsv" \
  --score "$tmp/score.tsv"
# Both boards must cover every published rate once.
awk -F'\t' '/^#/ || !h++ { next } $1 == "total" { if ($7 != 80) { printf "board %s covers %s rates, not 80\n", $2, $7; bad = 1 }
  else printf "board %s: %s rates; agrees %s, non-convergence %s, seed band %s, checked (restored) %s, our rate explained only %s, unexplained %s, not computed %s, undefined %s, fingerprint %s, indeterminate %s\n", $2, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16, $17 }
  END { exit bad }' "$tmp/score.tsv"
known=tests/paper/known_unexplained.tsv
awk -F'\t' '
  FILENAME == ARGV[1] { if (/^#/ || !hk++) next; listed[$1 "|" $2 "|" $3] = $4; next }
  /^#/ { next }
  !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["setup"] != "document" || ($c["printed"] != "yes" && $c["identified"] != "yes") { next }
  { k = $c["table"] "|" $c["slice"] "|" $c["key"]; n++; present[k] = 1
    # On the printed board the verdict, on the identified one its own (fingerprint rows);
    # a row on both is unexplained if either board says so.
    v = $c["printed"] == "yes" ? $c["verdict"] : $c["verdict_identified"]
    if ($c["identified"] == "yes" && $c["verdict_identified"] == "differs, unexplained") v = "differs, unexplained"
    count[v]++
    if (v == "differs, unexplained") {
      if (k in listed) { seen[k] = 1 }
      else { bad++; printf "UNLISTED unexplained rate: %s (published %s, reproduced %s)\n", k, $c["published"], $c["reproduced"] } }
    else if (k in listed) { bad++; printf "STALE entry in known_unexplained.tsv: %s is now \"%s\"; remove it\n", k, v } }
  END {
    for (k in listed) if (!(k in present)) { bad++; printf "STALE entry in known_unexplained.tsv: %s is not a stored document rate\n", k }
    printf "paper-scale document rates on either board: %d;", n
    for (v in count) printf " %s %d;", v, count[v]
    printf "\n"
    if (n == 0) { print "no paper-scale rate in the store"; exit 1 }
    exit bad > 0 }' "$known" "$tmp/rates.tsv"
