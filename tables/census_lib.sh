# Sourced by tables/store_census.sh, tables/beyond_plan.sh and the store's recomputations
# (tests/store/verify_store_full.sh, verify_sample.sh): one store file read by its own program
# in --census mode, a census's options beyond its levels, and the machine line of their
# headers.  Nothing is computed.

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

# machine_line: the CPU model and core count (the plan's calibration ran on this machine).
machine_line() {
  echo "$(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores"
}
