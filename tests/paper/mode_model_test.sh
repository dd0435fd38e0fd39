#!/bin/bash
# thesis_heat_mode_model against an independent recomputation: for every stored row of
# Table 4.7 (dt = dt0 exactly) the one-mode error max_k |g^k - exp(-mu k dt)| is recomputed
# here in awk from the row's theta, K, dt, N, dx and eps(|k|h) from `gpm smoothing`, and
# must equal the program's `predicted` to 1e-9 relative.  Then the model must account for
# the stored errors at the table's rate levels (measured/predicted within [0.9, 1.1]).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=${1:?usage: mode_model_test.sh BUILD_DIR SOURCE_DIR}
src=${2:?usage: mode_model_test.sh BUILD_DIR SOURCE_DIR}
data=$src/results/paper/thesis_table4_7_dtexact.tsv
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$build/thesis_heat_mode_model" --table 4.7 --data "$data" --out "$t/model.tsv" > /dev/null || exit 1
k=4.442882938158366  # pi sqrt 2
# eps per (weight, h) from gpm smoothing
awk -F'\t' '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { print $c["weight"] "\t" $c["h"] }' "$data" | sort -u > "$t/wh.tsv"
while IFS=$'\t' read -r w h; do
  e=$("$build/gpm" smoothing --weight "$w" --h "$h" --k "$k" | awk -F'\t' '/^#/ { next } !n++ { next } { print $3 }')
  printf '%s\t%s\t%s\n' "$w" "$h" "$e"
done < "$t/wh.tsv" > "$t/eps.tsv"
awk -F'\t' -v k="$k" '
  function abs(x) { return x < 0 ? -x : x }
  FNR == 1 { file++ }
  file == 1 { eps[$1, $2] = $3; next }
  /^#/ { next }
  !seen[file]++ { for (i = 1; i <= NF; i++) c[file, $i] = i; next }
  file == 2 { if ($c[2, "blew_up"] == "yes") next
    mu = 0.5 * k * k; dx = $c[2, "dx"]; d = 1.44 / ($c[2, "N"] * dx * dx) - 1
    th = $c[2, "theta"]; dt = $c[2, "dt"]; z = mu * (1 + d) * (1 - eps[$c[2, "weight"], $c[2, "h"]]) * dt
    g = (1 - (1 - th) * z) / (1 + th * z); worst = 0; gk = 1
    for (j = 0; j <= $c[2, "K"]; j++) { e = abs(gk - exp(-mu * j * dt)); if (e > worst) worst = e; gk *= g }
    want[$c[2, "weight"], $c[2, "theta"], $c[2, "level"]] = worst; next }
  { key = $c[3, "weight"] SUBSEP $c[3, "theta"] SUBSEP $c[3, "level"]; n++
    p = $c[3, "predicted"]
    if (!(key in want) || abs(p - want[key]) > 1e-9 * abs(want[key])) { bad++; print "differs: " $0 }
    if ($c[3, "level"] >= 8) { q = $c[3, "measured_over_predicted"]; if (q < 0.9 || q > 1.1) { far++; print "model misses: " $0 } } }
  END { printf "mode_model_test: %d rows recomputed, %d differ, %d at 2^-8/2^-9 outside [0.9, 1.1]\n", n, bad, far
        exit (n > 0 && bad == 0 && far == 0) ? 0 : 1 }' "$t/eps.tsv" "$data" "$t/model.tsv"
