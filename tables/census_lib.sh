# Sourced by tables/store_census.sh, tables/beyond_plan.sh and the store's recomputations
# (tests/store/verify_store_full.sh, verify_sample.sh): one store file read by its own program
# in --census mode, a census's options beyond its levels, and the machine line of their
# headers (also of tables/imoto_where.sh and bench/heat_propagator_check.sh); also a file's
# data rows without the columns that time a run (the comparisons of bench/time_heat_shared.sh
# and tests/mpi/mpi_matches_serial.sh).  Nothing is computed.

# census_options "CENSUS": a census's options beyond its levels (--only h15, --thetas 0), one
# space apart: what a recomputation of one of the file's units takes along (a file that holds
# some variants only).  Empty for none.
census_options() {
  awk '{ s = ""; for (i = 1; i <= NF; i++) if ($i == "--levels") i++; else s = s (s == "" ? "" : " ") $i; print s }' <<<"$1"
}

# census_read BUILD PROGRAM "ARGS" FILE: runs `PROGRAM ARGS --profile paper --out FILE --census`
# and sets census_line (its "[store] census" summary; empty when the census could not read
# the file, e.g. locked by a run writing it), census_missing (its missing-unit lines) and
# census_problem (the log's first line where there is no summary).
census_read() {
  local build=$1 program=$2 args=$3 file=$4 log
  # shellcheck disable=SC2086  # the options are words
  log=$("$build/$program" $args --profile paper --out "$file" --census 2>&1) || true
  census_line=$(grep '^\[store\] census ' <<<"$log" | head -1 || true)
  census_missing=$(grep '^\[store\]   missing: ' <<<"$log" || true)
  census_problem=
  [ -n "$census_line" ] || census_problem=$(grep -m1 . <<<"$log" | tr '\t' ' ')
}

# machine_line: the CPU model, its core count and, where fewer, the threads this run may use
# (the plan's calibration ran on this machine).  `nproc` alone honours OMP_NUM_THREADS, so
# lines written before this split say "1 cores" for a one-thread run on two cores.
machine_line() {
  local all threads
  all=$(nproc --all) threads=$(nproc)
  echo "$(lscpu | sed -n 's/^Model name: *//p' | head -1), $all cores$([ "$threads" = "$all" ] || echo ", $threads thread$([ "$threads" = 1 ] || echo s)")"
}

# data_rows FILE REGEX: FILE's data rows (header line included, `#` lines left out) without
# the columns whose names match REGEX (awk's ERE), each row its kept cells, tab-ended: two runs
# that made the same numbers print the same lines, whatever each took.
data_rows() {
  awk -F'\t' -v drop="$2" '/^#/ { next }
    !h++ { for (i = 1; i <= NF; i++) keep[i] = $i !~ drop }
    { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line $i "\t"; print line }' "$1"
}

# unit_key PROGRAM: the key columns besides the level whose values select one part of a level
# with --only, each part its own Laplacian or pass (so a level recomputed part by part costs
# about what it costs whole): Table 4.4's h rule and weight, Tables 4.1-4.3's reading and
# volumes, imoto's m, a heat file's weight.  Empty where a level goes whole.
unit_key() {
  case $1 in
    thesis_table4_4) echo h_rule,weight ;;
    thesis_table4_1|thesis_table4_2|thesis_table4_3) echo h_reading,volumes ;;
    imoto_fig5_table1) echo m ;;
    thesis_heat) echo weight ;;
  esac
}

# An awk function for the part a store row belongs to: its unit_key columns' values joined by
# ",", as --only takes them.  `col`: the column map by name; `uk`, `nk`: the key's columns
# (split on ",") and their count, 0 for none ("").
unit_part_awk='function unit_part(col, uk, nk,   p, i) {
  if (!nk) return ""
  p = $col[uk[1]]; for (i = 2; i <= nk; i++) p = p "," $col[uk[i]]
  return p }'

# An awk function for the part a verified.log line vouches for: its path's "--only PART" or
# "--weights PART" (verify_store_full.sh writes a part's line so, the latter for a heat file),
# "-" for a whole level.
line_part_awk='function line_part(path) {
  if (match(path, /--only [^ ]+/)) return substr(path, RSTART + 7, RLENGTH - 7)
  return match(path, /--weights [^ ]+/) ? substr(path, RSTART + 10, RLENGTH - 10) : "-" }'

# cheaper_path PROGRAM STEM FILE: the options of a store file's independent, cheaper
# recomputation (issue 58 item 3), "-" where it has none: Table 4.4's plain-CG files by the
# tau-preconditioned solver; Table 4.7's by their own stepping with that solver (2-3 implicit
# steps: at 2^-9 the Krylov subspace `auto` chose took 298-748 s against 120-171 s stored,
# measured 2026-12-06); the other heat files by the propagator with fewer predicted products,
# their implicit steps, if stepped and plain, preconditioned.  verify_store_full.sh --cheap and
# the store sample both take it from here.
cheaper_path() {
  local program=$1 stem=$2 file=$3 plain=
  grep -q '^# solver = ' "$file" || plain=1
  if [ "$program" = thesis_table4_4 ] && [ -n "$plain" ]; then echo "--solver tau"
  elif [ "$program" = thesis_heat ] && [[ $stem == thesis_table4_7* ]] && [ -n "$plain" ]; then echo "--solver tau"
  elif [ "$program" = thesis_heat ]; then echo "--propagator auto${plain:+ --solver tau}"
  else echo -; fi
}

# An awk function for a store row's predicted seconds by the cheaper path: Table 4.4's assembly
# plus its solve scaled by 15 iterations over its own count (the preconditioned solver's 11-13
# at every level measured, results/bench/pcg_*), any other row its stored time `$t` (a heat
# row's, an upper bound: its path is chosen only where it needs fewer products).  `col`: the
# column map by name.
cheaper_seconds_awk='function cheaper_s(col, t,   its) {
  if ("cg_iterations" in col) { its = $col["cg_iterations"]
    return its > 15 ? $col["assembly_s"] + $col["solve_s"] * 15 / its : $t }
  return $t }'

# An awk function for the threads a machine cell names: a store row's made_on ("AMD EPYC, 2
# threads, 2026-12-02") or a log line's machine ("AMD EPYC, 2 cores, 1 thread"; lines written
# before machine_line named threads say "1 cores" for a one-thread run): its ", N thread",
# else its ", N cores", else 1.  made_on_threads: the same for a store row, whose file may have
# no made_on column (`col`: the column map by name).
threads_in_awk='function threads_in(cell) {
  if (match(cell, /, [0-9]+ thread/)) return substr(cell, RSTART + 2, RLENGTH - 9) + 0
  if (match(cell, /, [0-9]+ cores/)) return substr(cell, RSTART + 2, RLENGTH - 8) + 0
  return 1 }
function made_on_threads(col) { return ("made_on" in col) ? threads_in($col["made_on"]) : 1 }'
