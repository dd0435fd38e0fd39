#!/bin/bash
# figure_rules.sh on two figures drawn here with gnuplot: one that keeps the rules (passes)
# and one with two series told apart only by colour, seven series in a panel and a series
# through two points (must fail, naming all three).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
here=$(cd "$(dirname "$0")" && pwd)
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/good" "$t/bad"
gnuplot -e "set terminal svg; set output '$t/good/ok.svg'; \
  plot x w lp lt 1 dt 1 pt 6 title 'a', 2*x w lp lt 2 dt 2 pt 4 title 'b', \
       3*x w l lc 'grey' title 'published rate'" || exit 1
gnuplot -e "set terminal svg; set output '$t/bad/clash.svg'; \
  plot x w l lt 1 dt 2 title 'p', 2*x w l lt 2 dt 2 title 'q', 3*x w lp dt 1 pt 1 title 's3', \
       4*x w lp dt 1 pt 2 title 's4', 5*x w lp dt 1 pt 3 title 's5', 6*x w lp dt 1 pt 4 title 's6', \
       7*x w lp dt 1 pt 5 title 's7'" || exit 1
printf '1 1\n2 4\n' > "$t/two.dat"
gnuplot -e "set terminal svg; set output '$t/bad/two.svg'; \
  plot '$t/two.dat' w lp pt 6 title 'two levels'" || exit 1
bash "$here/figure_rules.sh" "$t/good" || { echo "FAIL: a figure within the rules was rejected"; exit 1; }
out=$(bash "$here/figure_rules.sh" "$t/bad") && { echo "FAIL: the bad figure passed"; exit 1; }
for want in '"p" and "q" differ only in colour' '7 series (at most 6)' \
            '"two levels" is drawn through two points only'; do
  grep -qF "$want" <<<"$out" || { echo "FAIL: expected '$want' in:"; echo "$out"; exit 1; }
done
echo "figure_rules_test: the good figure passes, the bad one is rejected on all three counts"
