#!/usr/bin/env bash
# The whole-store recomputation (verify_store_full.sh) as a background run that outlives a
# shell and leaves the tree clean while it goes: frozen copies of the programs and scripts (so
# a rebuild or an edit does not change a run in progress), its own copy of the log, and a merge
# that appends the lines it has added since to the store's verified.log, to commit.  One run at
# a time per DIR.  Each line is sealed alone, so appending them is all a merge does.
#
# usage: verify_background.sh start BUILD STORE [verify_store_full.sh options...]
#        verify_background.sh merge STORE     append the new lines to STORE/verified.log
#        verify_background.sh status          the run's state, its programs, its last lines
#        verify_background.sh drain           no new jobs: the lanes finish what they hold
#   DIR: $VERIFY_BG_DIR, default /tmp/verify-bg (frozen build, scripts, log, progress)
export LC_ALL=C
set -euo pipefail
dir=${VERIFY_BG_DIR:-/tmp/verify-bg}
usage="usage: verify_background.sh start BUILD STORE [options...] | merge STORE | status | drain"
src=$(cd "$(dirname "$0")/../.." && pwd)
running() { [ -f "$dir/pid" ] && kill -0 "$(cat "$dir/pid")" 2>/dev/null; }
# The run's log lines past its copy of the store's log and those merged already.
unmerged() { echo $(( $(wc -l < "$dir/log") - $(cat "$dir/base") - $(cat "$dir/merged") )); }
case ${1:-} in
  start)
    [ $# -ge 3 ] || { echo "$usage" >&2; exit 2; }
    build=$2 store=$3; shift 3
    [ -x "$build/gpm" ] || { echo "verify_background.sh: $build/gpm not found" >&2; exit 2; }
    [ -f "$store/verified.log" ] || { echo "verify_background.sh: $store/verified.log not found" >&2; exit 2; }
    running && { echo "verify_background.sh: a run is going in $dir (pid $(cat "$dir/pid")); drain it or use another VERIFY_BG_DIR" >&2; exit 2; }
    store=$(cd "$store" && pwd)
    [ -f "$dir/log" ] && [ -f "$dir/base" ] && [ -f "$dir/merged" ] && [ "$(unmerged)" -gt 0 ] &&
      { echo "verify_background.sh: $dir/log holds lines not merged yet: merge them first" >&2; exit 2; }
    rm -rf "$dir" && mkdir -p "$dir/build" "$dir/src"
    find "$build" -maxdepth 1 -type f -executable -exec cp {} "$dir/build/" \;
    cp -r "$src/tests" "$src/tables" "$dir/src/"
    cp "$store/verified.log" "$dir/log"
    wc -l < "$dir/log" > "$dir/base"; echo 0 > "$dir/merged"; echo "$store" > "$dir/store"
    # Its own session at low weight: Linux shares the CPU between sessions (autogroups)
    # before nice counts, so without the autogroup's nice a shell's work gets half at best.
    # shellcheck disable=SC2016  # the inner script's words are its own ($0: DIR, $1: STORE)
    (cd "$src" && exec nohup setsid nice -n 10 bash -c 'echo $$ > "$0/pid"; echo 10 > /proc/self/autogroup 2>/dev/null || true
      VERIFY_STOP_FILE=$0/drain exec bash "$0/src/tests/store/verify_store_full.sh" "$0/build" "$1" --log "$0/log" "${@:2}"' \
      "$dir" "$store" "$@" >> "$dir/progress" 2>&1 < /dev/null) &
    for _ in 1 2 3 4 5 6 7 8 9 10; do [ -s "$dir/pid" ] && break; sleep 0.2; done
    echo "verify_background: started (pid $(cat "$dir/pid")), progress in $dir/progress; merge with: bash tests/store/verify_background.sh merge $store" ;;
  merge)
    [ $# -eq 2 ] || { echo "$usage" >&2; exit 2; }
    store=$2
    [ -f "$dir/log" ] || { echo "verify_background.sh: no run in $dir" >&2; exit 2; }
    [ "$(cd "$store" && pwd)" = "$(cat "$dir/store")" ] || { echo "verify_background.sh: the run in $dir verifies $(cat "$dir/store"), not $store" >&2; exit 2; }
    base=$(cat "$dir/base") merged=$(cat "$dir/merged")
    exec 9> "$dir/merge.lock"; flock 9
    new=$(unmerged)
    if [ "$new" -gt 0 ]; then
      tail -n +$((base + merged + 1)) "$dir/log" | head -n "$new" >> "$store/verified.log"
      echo $((merged + new)) > "$dir/merged"
    fi
    echo "verify_background: merged $new line(s) into $store/verified.log$(running || echo '; the run has ended')" ;;
  status)
    [ -f "$dir/pid" ] || { echo "verify_background: no run in $dir"; exit 0; }
    echo "verify_background: $(running && echo "running (pid $(cat "$dir/pid"))" || echo ended); $(unmerged) line(s) to merge"
    pgrep -af "^$dir/build/" | cut -c1-200 || true
    # What each lane took last (its start line: since when, the estimate) and the last results.
    awk '/ lane [^ ]+ starts / { for (i = 1; i <= NF; i++) if ($i == "lane") took[$(i + 1)] = $0; next }
      { last[++n] = $0 }
      END { for (k in took) print "last taken: " took[k]; for (i = (n > 2 ? n - 2 : 1); i <= n; i++) print last[i] }' "$dir/progress" ;;
  drain)
    running || { echo "verify_background: no run going in $dir"; exit 0; }
    : > "$dir/drain"
    echo "verify_background: draining: the lanes take no new job and end with the ones they hold" ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
