#!/usr/bin/env bash
# The Krylov propagator (src/gpm/solvers/heat_krylov.hpp) against the stepped rows of the
# result store: every heat file's coarse units, and one rate level per table under the
# identified reading (h15, V_i = dx^2, dt = dt0: Tables 4.6 and 4.7 at 2^-9; Table 4.5, cheap
# propagated, every stored reading at every stored level), recomputed with --propagator krylov into a scratch folder (the store is only read)
# and compared row by row: the largest relative difference of rel_error, rel_error_max and
# growth_max, and K, dt, steps_done and blew_up equal.  The stored rows were stepped with CG to
# 1e-10 per implicit step, so their θ > 0 errors carry that solver's own error (about 1e-6 of
# the error at Table 4.5's rate levels, tests/unit/test_heat_krylov.cpp); θ = 0 has no solver.
#
# usage: bench/heat_propagator_check.sh BUILD_DIR STORE_DIR OUT.tsv [coarse|rate|all]
#   Writes OUT.tsv (one row per file and level set) and prints it; resumable (a file and
#   level set already in OUT.tsv is skipped).  Long: the rate levels take about half an hour
#   on 2 cores.
export LC_ALL=C
set -euo pipefail
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/.." && pwd)/tables/census_lib.sh"
if [ $# -lt 3 ]; then
  echo "usage: bench/heat_propagator_check.sh BUILD_DIR STORE_DIR OUT.tsv [coarse|rate|all]" >&2
  exit 2
fi
build=$1 store=$2 out=$3 which=${4:-all}
case $which in coarse|rate|all) ;; *) echo "heat_propagator_check.sh: '$which' is not coarse, rate or all" >&2; exit 2;; esac
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
columns="file	levels	rows	max_rel_rel_error	max_rel_rel_error_max	max_rel_growth_max	max_rel_rel_error_theta0	texts_equal	subspace_max	krylov_s	stepped_s_stored	stepped_made_on"
if [ ! -s "$out" ]; then
  {
    echo "# program = bench/heat_propagator_check.sh"
    echo "# what = thesis_heat --propagator krylov against the stored (stepped, CG 1e-10) rows, per file and levels"
    echo "# machine = $(machine_line)"
    echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
    echo "# written_utc = $(date -u +%FT%TZ)"
    echo "$columns"
  } > "$out"
fi

# compare STORED NEW: one summary line of the rows NEW holds, matched by (weight, theta, level).
compare() {
  awk -F'\t' -v OFS='\t' '
    FNR == 1 { f++ }
    /^#/ { next }
    !hdr[f] { for (i = 1; i <= NF; i++) col[f, $i] = i; hdr[f] = 1; next }
    function v(file, name) { return $(col[file, name]) }
    function rel(a, b,   d, m) { d = a - b; if (d < 0) d = -d; m = (a < 0 ? -a : a); if ((b < 0 ? -b : b) > m) m = (b < 0 ? -b : b); return m > 0 ? d / m : 0 }
    f == 1 { k = v(1, "weight") "|" v(1, "theta") "|" v(1, "level")
             for (c in want) S[k, c] = v(1, c); S[k] = 1; made[k] = v(1, "made_on"); sec[k] = v(1, "seconds"); next }
    f == 2 { k = v(2, "weight") "|" v(2, "theta") "|" v(2, "level")
             if (!(k in S)) { missing++; next }
             rows++
             for (c in num) { r = rel(S[k, c], v(2, c)); if (r > mx[c]) mx[c] = r }
             if (v(2, "theta") == 0) { r = rel(S[k, "rel_error"], v(2, "rel_error")); if (r > mx0) mx0 = r }
             for (c in txt) if (S[k, c] != v(2, c)) bad++
             if (v(2, "subspace") > msub) msub = v(2, "subspace")
             ks += v(2, "seconds"); ss += sec[k]; mo = made[k] }
    BEGIN { split("rel_error rel_error_max growth_max", a, " "); for (i in a) { num[a[i]] = 1; want[a[i]] = 1 }
            split("K dt steps_done blew_up", b, " "); for (i in b) { txt[b[i]] = 1; want[b[i]] = 1 } }
    END { if (missing) { print "rows missing from the store: " missing > "/dev/stderr"; exit 1 }
          printf "%d\t%.3g\t%.3g\t%.3g\t%.3g\t%s\t%d\t%.1f\t%.1f\t%s\n", rows, mx["rel_error"], mx["rel_error_max"], mx["growth_max"], mx0, (bad ? "no" : "yes"), msub, ks, ss, mo }' "$1" "$2"
}

# run FILE LEVELS ARGS...: the file's units at LEVELS by the Krylov propagator, compared.
run() {
  local file=$1 levels=$2
  shift 2
  if awk -F'\t' -v f="$file" -v l="$levels" '$1 == f && $2 == l { found = 1 } END { exit !found }' "$out"; then
    echo "== $file at $levels: in $out already"
    return
  fi
  echo "== $file at $levels: thesis_heat $* --levels $levels --propagator krylov"
  rm -f "$scratch/$file.tsv"
  nice -n 19 "$build/thesis_heat" "$@" --levels "$levels" --propagator krylov --profile paper \
    --out "$scratch/$file.tsv" >&2
  printf '%s\t%s\t%s\n' "$file" "$levels" "$(compare "$store/$file.tsv" "$scratch/$file.tsv")" >> "$out"
  tail -1 "$out"
}

listing=$("$build/gpm" study --store-rows)
if [ "$which" != rate ]; then
  while IFS=$'\t' read -r _study file program args _census coarse _slice; do
    [ "$program" = thesis_heat ] || continue
    [ "$args" = - ] && args=""
    # shellcheck disable=SC2086  # the arguments are words
    run "$file" "${coarse#--levels }" $args
  done <<<"$listing"
fi
if [ "$which" != coarse ]; then
  # Table 4.5 is cheap propagated: every stored reading at every level it holds.
  run thesis_table4_5 4,5,6,7,8 --table 4.5
  run thesis_table4_5_h15 4,5,6,7,8 --table 4.5 --h-rule h15
  run thesis_table4_5_cellvol 5,7,8 --table 4.5 --volumes cell
  run thesis_table4_5_h15_dtexact_cellvol 4,5,6,7,8 --table 4.5 --h-rule h15 --dt-rule exact --volumes cell
  run thesis_table4_6_h15_dtexact_cellvol 9 --table 4.6 --h-rule h15 --dt-rule exact --volumes cell
  run thesis_table4_7_h15_dtexact_cellvol 9 --table 4.7 --h-rule h15 --dt-rule exact --volumes cell
fi
column -t -s $'\t' < <(grep -v '^#' "$out")
