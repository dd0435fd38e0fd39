#!/usr/bin/env bash
# The store's whitelist (results/paper/.gitignore) against the study registry: git must not
# ignore any file the registry puts in the store (a run's rows would land and never be
# committed), and every whitelisted name pattern must name a file of the registry (a stale line
# whitelists nothing).  Needs git (a clone); elsewhere it says so and passes.
# usage: whitelist.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=$(cd "${1:?usage: whitelist.sh BUILD_DIR SOURCE_DIR}" && pwd) || exit 2
cd "${2:?usage: whitelist.sh BUILD_DIR SOURCE_DIR}" || exit 2
git rev-parse --git-dir >/dev/null 2>&1 || { echo "whitelist: not a git clone; nothing to check"; exit 0; }
names=$("$build/gpm" study --store-rows | cut -f2)
[ -n "$names" ] || { echo "FAIL: the registry lists no store file"; exit 1; }
fail=0 n=0
for name in $names; do
  n=$((n + 1))
  if git check-ignore -q "results/paper/$name.tsv"; then
    echo "FAIL: results/paper/$name.tsv is a store file of the registry but git ignores it (results/paper/.gitignore)"
    fail=1
  fi
done
while IFS= read -r line; do
  case $line in '!'*/*) continue ;; '!'*.tsv) pattern=${line#!} ;; *) continue ;; esac  # */*: saved parts
  hit=0
  for name in $names; do
    # shellcheck disable=SC2053  # the pattern is a glob on purpose
    [[ "$name.tsv" == $pattern ]] && { hit=1; break; }
  done
  [ $hit -eq 1 ] || { echo "FAIL: results/paper/.gitignore whitelists '$pattern', which names no store file of the registry"; fail=1; }
done < results/paper/.gitignore
[ $fail -eq 0 ] && echo "whitelist: the $n store files of the registry are committed, every whitelisted pattern names one"
exit $fail
