#!/usr/bin/env bash
# Where in Ω the largest error of Imoto's Lap1 and Lap2 at m = 5 sits (issue: the m = 5 rates),
# per level and jitter realization: one `gpm trunc` run each (uniform volumes |Ω_H|/N, the
# test function sin 2π(x+y), h = 2.6·2^(5/m−5)·Δx^(1/m) as in Imoto §5).  The error must
# equal the stored Table 1 row of the same (level, seed); the location is what the study's
# data file does not record.  Levels 2^-9..2^-11 for seeds 1-3 and the plain grid, 2^-12 for
# seed 1 (a quarter of an hour each there).  Resumable: finished rows are kept.
# usage: imoto_where.sh BUILD_DIR OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
# shellcheck source=tables/census_lib.sh
. "$(dirname "$0")/census_lib.sh"
build=$1 out=$2
cols='weight\tvariant\tlevel\tdx\th\trel_error\tworst_x\tworst_y\tworst_to_boundary_over_h\ttime_s'
if [ ! -f "$out" ]; then
  {
    echo "# program = tables/imoto_where.sh"
    echo "# what = the particle of Omega where the relative l-inf error of Lap1/Lap2 (m = 5) is largest"
    echo "# runs = $build/gpm trunc --operator lap --m 5 --function sin2pi --volumes uniform"
    echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
    echo "# gpm_fingerprint = $("$build/gpm" fingerprint gpm 2>/dev/null | tail -1)"
    echo "# machine = $(machine_line)"
    echo "# started_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    printf "$cols\n"
  } > "$out"
fi
run() {  # run WEIGHT VARIANT LEVEL
  local w=$1 v=$2 k=$3 opt
  grep -q "^$w	$v	$k	" "$out" && return 0
  case $v in plain) opt="--jitter 0";; seed*) opt="--seed ${v#seed}";; esac
  "$build/gpm" trunc --operator lap --weight "$w" --m 5 --dx "2^-$k" $opt | awk -F'\t' -v w="$w" -v v="$v" -v k="$k" '
    /^#/ { next } !h++ { for (i=1;i<=NF;i++) c[$i]=i; next }
    { printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", w, v, k, $c["dx"], $c["h"], $c["rel_error"],
        $c["worst_x"], $c["worst_y"], $c["worst_to_boundary_over_h"], $c["time_s"] }' > "$out.row"
  cat "$out.row" >> "$out" && rm -f "$out.row"
  echo "imoto_where: $w $v 2^-$k done" >&2
}
for k in 9 10 11; do
  for v in seed1 seed2 seed3 plain; do for w in Lap1 Lap2; do run $w $v $k; done; done
done
# At 2^-12 seed 1 only: the plain grid's maximum sits on whole lines (its place says nothing).
for w in Lap1 Lap2; do run $w seed1 12; done
