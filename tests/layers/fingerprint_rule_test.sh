#!/bin/bash
# The code fingerprint by rule (cmake/fingerprint.cmake), on a copy of the sources: a change of
# h in the registry (studies/define) moves the fingerprint of the programs that compute with
# it; an edit of the judging room (studies/judge), of the store's census
# (studies/define/census), of prices (studies/define/pricing, cost_model) or of the registry's
# bookkeeping (studies/define/registry_books: a seed's store file) moves none; an
# edit of a shared program body (src/apps/tables/) moves the programs that include it and no
# other; so does an edit of a solver (the include closure); a core source in a folder no rule
# names stops the script, naming it.
# usage: fingerprint_rule_test.sh SOURCE_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
src=${1:?usage: fingerprint_rule_test.sh SOURCE_DIR}
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/tree"
cp -r "$src/src" "$src/bench" "$t/tree/"
fp() {  # fp OUT: run the script on the copy; print thesis_heat's and core_voronoi's fingerprints
  cmake -DSRC="$t/tree" -DOUT="$1" -DFLAGS=test -P "$src/cmake/fingerprint.cmake" >/dev/null 2>"$t/err" || return 1
  grep -o '{"\(thesis_heat\|core_voronoi\)", "[0-9a-f]*"}' "$1" | tr '\n' ' '
}
fp_of() {  # fp_of PROGRAM OUT: that program's fingerprint in a generated file
  grep -o "{\"$1\", \"[0-9a-f]*\"}" "$2"
}
fail=0
before=$(fp "$t/a.cpp") || { echo "FAIL: the script failed on the sources:"; cat "$t/err"; exit 1; }
[ -n "$before" ] || { echo "FAIL: no fingerprint of thesis_heat or core_voronoi in the output"; exit 1; }
# h of the heat and Poisson units scaled by 1.01 where the registry computes it.
reg="$t/tree/src/gpm/studies/define/registry.cpp"
grep -q 'pde_h(' "$reg" || { echo "FAIL: the registry no longer computes h with pde_h (update this test)"; exit 1; }
sed -i '0,/pde_h(/s//1.01 * pde_h(/' "$reg"
moved=$(fp "$t/b.cpp")
h_before=$(grep -o '{"thesis_heat", "[0-9a-f]*"}' <<<"$before")
h_after=$(grep -o '{"thesis_heat", "[0-9a-f]*"}' <<<"$moved")
[ "$h_before" != "$h_after" ] || { echo "FAIL: a change of h in studies/define left thesis_heat's fingerprint as it was"; fail=1; }
cp "$src/src/gpm/studies/define/registry.cpp" "$reg"
# A judging edit: no stored number depends on it.
echo "// an edit of the judging room" >> "$t/tree/src/gpm/studies/judge/verdicts.cpp"
same=$(fp "$t/c.cpp")
[ "$same" = "$before" ] || { echo "FAIL: an edit of studies/judge moved a fingerprint ($before -> $same)"; fail=1; }
# A census edit (a level the store must hold): no stored number depends on it.
echo "// a level added to the census" >> "$t/tree/src/gpm/studies/define/census.cpp"
same=$(fp "$t/e.cpp")
[ "$same" = "$before" ] || { echo "FAIL: an edit of studies/define/census moved a fingerprint ($before -> $same)"; fail=1; }
cp "$src/src/gpm/studies/define/census.cpp" "$t/tree/src/gpm/studies/define/census.cpp"
# A price edit (the unit pricer, the cost model): no stored number depends on it.
echo "// a price changed" >> "$t/tree/src/gpm/studies/define/pricing.cpp"
echo "// a work estimate changed" >> "$t/tree/src/gpm/studies/define/cost_model.cpp"
same=$(fp "$t/f.cpp")
[ "$same" = "$before" ] || { echo "FAIL: an edit of the pricer or the cost model moved a fingerprint ($before -> $same)"; fail=1; }
cp "$src/src/gpm/studies/define/pricing.cpp" "$src/src/gpm/studies/define/cost_model.cpp" "$t/tree/src/gpm/studies/define/"
# A bookkeeping edit of the registry (a seed's store file, a figure, a price): none moves.
books="$t/tree/src/gpm/studies/define/registry_books.cpp"
grep -q '"thesis_table4_4_cellvol_seed"' "$books" || { echo "FAIL: the registry's books no longer list Table 4.4's seeds (update this test)"; exit 1; }
sed -i 's/for (const char\* seed : {"2", "3", "4", "5"})/for (const char* seed : {"2", "3", "4", "5", "6"})/' "$books"
grep -q '"5", "6"})' "$books" || { echo "FAIL: the test's seed edit did not apply (update this test)"; exit 1; }
same=$(fp "$t/h.cpp")
[ "$same" = "$before" ] || { echo "FAIL: a seed added to the registry's store files moved a fingerprint ($before -> $same)"; fail=1; }
cp "$src/src/gpm/studies/define/registry_books.cpp" "$books"
# A shared program body (src/apps/tables/) moves the programs that include it and no other.
body=$(grep -l '^#include "apps/tables/' "$t/tree/src/apps/"*.cpp | head -1)
[ -n "$body" ] || { echo "FAIL: no program includes a shared body (update this test)"; exit 1; }
user=$(basename "$body" .cpp)
inc=$(grep -o -m1 'apps/tables/[A-Za-z0-9_]*\.hpp' "$body")
cmake -DSRC="$t/tree" -DOUT="$t/g0.cpp" -DFLAGS=test -P "$src/cmake/fingerprint.cmake" >/dev/null 2>&1
echo "// an edit of the shared body" >> "$t/tree/src/${inc%.hpp}.cpp"
same=$(fp "$t/g.cpp")
[ "$same" = "$before" ] || { echo "FAIL: an edit of ${inc%.hpp}.cpp moved thesis_heat's or core_voronoi's fingerprint"; fail=1; }
[ "$(fp_of "$user" "$t/g0.cpp")" != "$(fp_of "$user" "$t/g.cpp")" ] ||
  { echo "FAIL: an edit of ${inc%.hpp}.cpp left $user's fingerprint, which includes it, as it was"; fail=1; }
# The include closure: an edit of the Krylov propagator moves the heat program's fingerprint
# and not core_voronoi's, which is not built from it; an edit of a source named after no header
# (weights/weight_registry.cpp, the weights' table) moves both, which include its header.
cmake -DSRC="$t/tree" -DOUT="$t/k0.cpp" -DFLAGS=test -P "$src/cmake/fingerprint.cmake" >/dev/null 2>&1
echo "// an edit of the propagator" >> "$t/tree/src/gpm/solvers/heat_krylov.cpp"
cmake -DSRC="$t/tree" -DOUT="$t/k1.cpp" -DFLAGS=test -P "$src/cmake/fingerprint.cmake" >/dev/null 2>&1
[ "$(fp_of thesis_heat "$t/k0.cpp")" != "$(fp_of thesis_heat "$t/k1.cpp")" ] ||
  { echo "FAIL: an edit of solvers/heat_krylov.cpp left thesis_heat's fingerprint as it was"; fail=1; }
[ "$(fp_of core_voronoi "$t/k0.cpp")" = "$(fp_of core_voronoi "$t/k1.cpp")" ] ||
  { echo "FAIL: an edit of solvers/heat_krylov.cpp moved core_voronoi's fingerprint (not in its closure)"; fail=1; }
cp "$src/src/gpm/solvers/heat_krylov.cpp" "$t/tree/src/gpm/solvers/heat_krylov.cpp"
[ ! -e "$t/tree/src/gpm/weights/weight_registry.hpp" ] || { echo "FAIL: weight_registry.cpp now has a header (update this test)"; exit 1; }
echo "// an edit of the weights' table" >> "$t/tree/src/gpm/weights/weight_registry.cpp"
cmake -DSRC="$t/tree" -DOUT="$t/k2.cpp" -DFLAGS=test -P "$src/cmake/fingerprint.cmake" >/dev/null 2>&1
for p in thesis_heat core_voronoi; do
  [ "$(fp_of $p "$t/k0.cpp")" != "$(fp_of $p "$t/k2.cpp")" ] ||
    { echo "FAIL: an edit of weights/weight_registry.cpp (named after no header) left $p's fingerprint as it was"; fail=1; }
done
cp "$src/src/gpm/weights/weight_registry.cpp" "$t/tree/src/gpm/weights/weight_registry.cpp"
# A folder no rule names.
mkdir -p "$t/tree/src/gpm/newroom" && echo "int x;" > "$t/tree/src/gpm/newroom/x.cpp"
if fp "$t/d.cpp" >/dev/null; then echo "FAIL: a core source in an unnamed folder was accepted"; fail=1
else grep -q "src/gpm/newroom/x.cpp" "$t/err" || { echo "FAIL: the refusal does not name the file:"; cat "$t/err"; fail=1; }; fi
[ $fail -eq 0 ] && echo "fingerprint rule: h in define moves it, judge, the census, prices and the registry's books do not, a shared body only its own programs', the propagator only the heat program's, a source named after no header its includers', an unnamed folder is refused"
exit $fail
