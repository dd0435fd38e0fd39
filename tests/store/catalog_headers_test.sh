#!/bin/bash
# Every study of the catalog writes the columns the catalog names: each one is run through
# `gpm study NAME` at a small level and the header line of its data file is compared with
# the `header` of `gpm study --list` (the catalog's columns, and the store's provenance
# columns for a study written through the unit cache).  (A column added in a program but not in the catalog,
# or the reverse, fails here.)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=$(cd "${1:?usage: catalog_headers_test.sh BUILD_DIR}" && pwd) || exit 2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$build/gpm" study --list > "$t/list.tsv" || exit 1
bad=0 n=0
while IFS=$'\t' read -r name cols; do
  level=4; [ "$name" = core_voronoi ] && level=3
  if ! (cd "$t" && "$build/gpm" study "$name" --levels "$level" --out "$t/$name.tsv" > "$t/$name.log" 2>&1); then
    echo "FAIL: $name did not run:"; tail -3 "$t/$name.log"; bad=$((bad + 1)); continue
  fi
  got=$(grep -v '^#' "$t/$name.tsv" | head -1 | tr '\t' ',')
  n=$((n + 1))
  if [ "$got" != "$cols" ]; then
    echo "FAIL: $name writes  $got"; echo "      catalog says $cols"; bad=$((bad + 1))
  fi
done < <(awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
                     { print $c["study"] "\t" $c["header"] }' "$t/list.tsv")
echo "catalog_headers_test: $n studies run, $bad differ from the catalog"
[ "$n" -gt 0 ] && [ "$bad" -eq 0 ]
