#!/usr/bin/env bash
# The heat tables' set-up readings at the documents' rate levels, into the result store, in
# the background (nice 19, resumable: a finished unit is never recomputed).  One line of the
# queue per run; the store files are named by the reading (thesis_heat's {reading} suffix,
# the names of the registry's store files: gpm study --store-files, column slice).  The program is a frozen copy of the
# build's thesis_heat (BIN), so that rebuilding the working tree meanwhile does not change the
# code that writes.
#
# usage: bench/run_heat_readings.sh BIN QUEUE_FILE [LOG]
#   QUEUE_FILE lines, either one reading:
#     TABLE READING THETAS LEVELS                    e.g.  4.6 h15_cell_exact 0 5,6,7,8,9
#   READING: h10|h15, then optional _cell (V_i = dx^2) and _exact (dt = dt0); or a reading
#   matrix, every combination in one run (the series of one Laplacian advance together):
#     TABLE H_RULES VOLUMES DT_RULES THETAS LEVELS   e.g.  4.5 h15 lattice,cell fit,exact 0,0.5,1 8
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
bin=$1 queue=$2 log=${3:-/dev/stderr}
store=results/paper
while read -r table a b c d e; do
  case $table in ''|'#'*) continue ;; esac
  if [ -n "$e" ]; then  # the matrix form
    h_rules=$a volumes=$b dt_rules=$c thetas=$d levels=$e
  else
    reading=$a thetas=$b levels=$c h_rules=${a%%_*} volumes=lattice dt_rules=fit
    case $reading in *_cell*) volumes=cell ;; esac
    case $reading in *_exact*) dt_rules=exact ;; esac
  fi
  out="$store/thesis_table${table/./_}{reading}.tsv"
  echo "== $(date -u +%FT%TZ) $table h $h_rules volumes $volumes dt $dt_rules theta $thetas levels $levels" >>"$log"
  nice -n 19 "$bin" --table "$table" --h-rule "$h_rules" --volumes "$volumes" --dt-rule "$dt_rules" \
    --thetas "$thetas" --levels "$levels" --profile paper --out "$out" >>"$log" 2>&1 ||
    echo "   FAILED (exit $?)" >>"$log"
done <"$queue"
echo "== $(date -u +%FT%TZ) queue done" >>"$log"
