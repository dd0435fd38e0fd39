#!/usr/bin/env bash
# The heat tables' set-up readings at the documents' rate levels, into the result store, in
# the background (nice 19, resumable: a finished unit is never recomputed).  One line of the
# queue below per (table, reading, θ subset, levels); the reading's store file is named by
# tables/store_lib.sh's heat_file.  The program is a frozen copy of the build's thesis_heat
# (BIN), so that rebuilding the working tree meanwhile does not change the code that writes.
#
# usage: bench/run_heat_readings.sh BIN QUEUE_FILE [LOG]
#   QUEUE_FILE lines: TABLE READING THETAS LEVELS   e.g.  4.6 h15_cell_exact 0 5,6,7,8,9
#   READING: h10|h15, then optional _cell (V_i = dx^2) and _exact (dt = dt0).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
bin=$1 queue=$2 log=${3:-/dev/stderr}
store=results/paper
. tables/store_lib.sh
while read -r table reading thetas levels; do
  case $table in ''|'#'*) continue ;; esac
  args=(--table "$table" --h-rule "${reading%%_*}" --thetas "$thetas" --levels "$levels")
  case $reading in *_cell*) args+=(--volumes cell) ;; esac
  case $reading in *_exact*) args+=(--dt-rule exact) ;; esac
  file=$(heat_file "$store" "${table/./_}" "$reading") || exit 2
  echo "== $(date -u +%FT%TZ) $table $reading theta $thetas levels $levels -> $file" >>"$log"
  nice -n 19 "$bin" "${args[@]}" --profile paper --out "$file" >>"$log" 2>&1 ||
    echo "   FAILED (exit $?)" >>"$log"
done <"$queue"
echo "== $(date -u +%FT%TZ) queue done" >>"$log"
