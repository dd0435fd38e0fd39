#!/usr/bin/env bash
# The bad-input table (make test): every row of CASES runs one command in a fresh empty
# directory and asserts what it must do with bad input — the exit code, a piece of its
# message, and which files the directory holds afterwards (for a refusal: exactly what the
# row's setup made, so nothing was written, replaced or left behind).  Covering a new option
# is adding a row.
#
# usage: run_cases.sh BUILD_DIR CASES
#
# CASES is tab-separated, one case per line ('#' lines and blank lines are skipped):
#   exit     the exit code the command must return
#   message  a fixed string its stdout + stderr must contain ('-': none); on a non-zero exit
#            its stderr must also be exactly one line (the program's one-line error)
#   setup    a bash command run first in the directory, with BUILD_DIR first on PATH ('-':
#            none); what it leaves is the
#            baseline the listing is compared with
#   command  a bash command run in the directory with BUILD_DIR first on PATH
#   after    the directory's files afterwards, space-separated and sorted, paths relative to
#            it ('-': exactly the baseline, every file's content unchanged)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=$(cd "$1" && pwd)
cases=$2
[ -d "$build" ] && [ -f "$cases" ] || { echo "usage: run_cases.sh BUILD_DIR CASES" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

listing() { (cd "$1" && find . -mindepth 1 | sed 's|^\./||' | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//'); }
# Contents of the regular files (through no link), to see that a refusal changed none.
sums() { (cd "$1" && find . -type f -exec md5sum {} + | LC_ALL=C sort); }

n=0 failed=0 lineno=0
while IFS= read -r line || [ -n "$line" ]; do
  lineno=$((lineno + 1))
  case "$line" in '' | '#'*) continue ;; esac
  IFS=$'\t' read -r want message setup command after extra <<<"$line"
  if [ -z "${after:-}" ] || [ -n "${extra:-}" ] || ! [[ "$want" =~ ^[0-9]+$ ]]; then
    echo "FAIL $cases:$lineno: malformed row (need 5 tab-separated columns): $line"
    failed=$((failed + 1))
    continue
  fi
  n=$((n + 1))
  dir=$work/case$n
  mkdir "$dir"
  if [ "$setup" != "-" ] && ! (cd "$dir" && PATH="$build:$PATH" bash -c "$setup") >/dev/null 2>&1; then
    echo "FAIL $cases:$lineno: setup failed: $setup"
    failed=$((failed + 1))
    continue
  fi
  base=$(listing "$dir")
  base_sums=$(sums "$dir")
  (cd "$dir" && PATH="$build:$PATH" timeout 120 bash -c "$command") >"$work/out" 2>"$work/err"
  rc=$?
  problems=()
  [ "$rc" -eq "$want" ] || problems+=("exit $rc, expected $want")
  if [ "$message" != "-" ] && ! cat "$work/out" "$work/err" | grep -qF -- "$message"; then
    problems+=("message lacks '$message'")
  fi
  if [ "$want" -ne 0 ]; then
    lines=$(wc -l <"$work/err")
    [ "$lines" -eq 1 ] || problems+=("stderr has $lines lines, expected one")
  fi
  [ "$after" = "-" ] && expect=$base || expect=$after
  got=$(listing "$dir")
  [ "$got" = "$expect" ] || problems+=("files afterwards: '$got', expected '$expect'")
  if [ "$after" = "-" ] && [ "$(sums "$dir")" != "$base_sums" ]; then
    problems+=("a file of the setup was changed")
  fi
  if [ ${#problems[@]} -gt 0 ]; then
    failed=$((failed + 1))
    echo "FAIL $cases:$lineno: $command"
    for p in "${problems[@]}"; do echo "     $p"; done
    sed 's/^/     stderr: /' "$work/err" | head -5
  else
    echo "ok   $command  => exit $rc $(head -1 "$work/err" | cut -c1-160)"
  fi
done <"$cases"
echo "bad input: $n cases, $failed failed"
[ "$n" -gt 0 ] && [ "$failed" -eq 0 ]
