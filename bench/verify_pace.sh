#!/usr/bin/env bash
# How fast a machine recomputes the store, against the machines that made it: each "agree" line
# of verified.log written on a machine matching PATTERN, its seconds over the level's stored
# seconds on one thread (each row's time times the threads its made_on cell names), with the
# storage the rows name (a matrix-free heat product evaluates the kernel again, an assembled
# one reads memory; bench_limit tells the two apart on a machine: results/bench/limit_*).  A
# pace of 1 is the made rows' speed; a shared run's seconds cover its tables together (its
# path names them), so its pace is an upper bound.
# usage: verify_pace.sh STORE LOG PATTERN OUT.tsv [SINCE [UNTIL]]   (PATTERN: an awk ERE on the
#        machine cell; SINCE, UNTIL: only lines dated at or after SINCE and before UNTIL, e.g.
#        2026-12-07T07:41 2026-12-07T10:41, one session's)
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
# shellcheck source=tables/census_lib.sh
. "$(cd "$(dirname "$0")/.." && pwd)/tables/census_lib.sh"
[ $# -ge 4 ] && [ $# -le 6 ] || { echo "usage: bench/verify_pace.sh STORE LOG PATTERN OUT.tsv [SINCE [UNTIL]]" >&2; exit 2; }
store=$1 log=$2 pattern=$3 out=$4 since=${5:-} until=${6:-}
[ -d "$store" ] || { echo "verify_pace.sh: store '$store' is not a directory" >&2; exit 2; }
[ -f "$log" ] || { echo "verify_pace.sh: log '$log' not found" >&2; exit 2; }
tmp=$(mktemp "$out.XXXXXX"); trap 'rm -f "$tmp"' EXIT
{
  echo "# program = bench/verify_pace.sh"
  echo "# what = seconds of a verify-store-full line over its level's stored seconds on one thread, by storage"
  echo "# log = $log"
  echo "# machine_pattern = $pattern"
  [ -z "$since" ] || echo "# since = $since"
  [ -z "$until" ] || echo "# until = $until"
  echo "# git_revision = $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%FT%TZ)"
  printf 'file\tlevel\tprogram\tstorage\tseconds\tstored_s\tone_thread_stored_s\tpace\tmachine\tpath\n'
  awk -F'\t' -v pat="$pattern" -v since="$since" -v until="$until" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["verdict"] == "agree" && $c["machine"] ~ pat && $c["date"] >= since && (until == "" || $c["date"] < until) {
      print $c["file"], $c["level"], $c["program"], $c["seconds"], $c["stored_s"], $c["machine"], $c["path"], line_part($c["path"]), $c["rows"] }
    '"$line_part_awk" OFS='\t' "$log" |
  while IFS=$'\t' read -r file level program secs stored machine path part compared; do
    f=$store/$file.tsv
    [ -f "$f" ] || { echo "verify_pace.sh: $f (named by the log) is missing" >&2; exit 4; }
    # A part's line (its path ending "--only PART" or "--weights PART", verify_store_full.sh)
    # is priced by its rows, unless it compared every row of the level (a thesis_heat "part"
    # under --only, which it never read, recomputed the whole level).
    awk -F'\t' -v L="$level" -v part="$part" -v compared="$compared" -v ukey="$(unit_key "$program")" '/^#/ { next }
      !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; t = ("seconds" in c) ? c["seconds"] : c["time_s"]
           nk = split(ukey, uk, ","); next }
      $c["level"] == L { n++; g = part == "-" || unit_part(c, uk, nk) == part
        if (!($t in seen)) { seen[$t] = 1; all += made_on_threads(c) * $t; if (g) w += made_on_threads(c) * $t }
        if ("storage" in c) { sa[$c["storage"]] = 1; if (g) st[$c["storage"]] = 1 } }
      '"$unit_part_awk"'
      '"$threads_in_awk"'
      END { if (compared + 0 >= n) { w = all; delete st; for (x in sa) st[x] = 1 }
            s = ""; for (x in st) s = s (s == "" ? "" : "+") x; printf "%s\t%.1f\n", (s == "" ? "-" : s), w }' "$f" |
    { IFS=$'\t' read -r storage one
      awk -v OFS='\t' -v a="$file" -v l="$level" -v p="$program" -v g="$storage" -v s="$secs" -v st="$stored" \
          -v o="$one" -v m="$machine" -v q="$path" \
          'BEGIN { print a, l, p, g, s, st, o, (o > 0 ? sprintf("%.2f", s / o) : "NA"), m, q }'; }
  done | sort -t$'\t' -k4,4 -k8,8g
} > "$tmp"
mv "$tmp" "$out"; trap - EXIT
# The pace by storage over the levels of a minute or more on one thread (below, start-up and
# rounding of the seconds decide): lines, smallest, median, largest.
awk -F'\t' '/^#/ || $1 == "file" || $7 < 60 { next } { n[$4]++; v[$4, n[$4]] = $8 }
  END { for (g in n) { m = n[g]; printf "verify_pace: %-24s %3d lines, pace %s .. %s .. %s\n", g, m, v[g, 1], v[g, int((m + 1) / 2)], v[g, m] } }' "$out" | sort
