#!/usr/bin/env bash
# Adding a study takes what docs/reference.md ("How to add") says and nothing more: one entry
# in the study registry (src/gpm/studies/define/registry.cpp) and its unit body
# (src/apps/<name>.cpp).  Proved on a copy of the tree (issue 57, item 4): a throwaway study
# is added there by those two files only, and the copy's own build, catalog, make rules,
# make run, cache, plan and layer and fingerprint rules take it.  tests/unit/
# test_registry_example.cpp checks the same entry in one process; this checks the files.
#
# The copy's build shares this build's compiler cache (CMakeLists.txt: ccache, paths relative
# to the tree), so it compiles the two changed files and links; without ccache it compiles
# everything it builds (minutes).  It leaves nothing behind (BUILD/add_study_copy is removed).
#
# usage: add_study_test.sh BUILD SOURCE
export LC_ALL=C
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: add_study_test.sh BUILD SOURCE" >&2; exit 2; }
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
name=scratch_interpolant
work=$build/add_study_copy tree=$build/add_study_copy/tree
fail() { echo "add_study_test: FAIL: $*" >&2; exit 1; }
rm -rf "$work"
trap 'rm -rf "$work"' EXIT
mkdir -p "$tree"

# --- a copy of the tree: the files git tracks or would track ---------------------------------
git -C "$src" rev-parse --git-dir >/dev/null 2>&1 || fail "$src is not a git checkout (the copy is made from git's file list)"
(cd "$src" && git ls-files -z -co --exclude-standard | tar --null -T - -cf -) | tar -C "$tree" -xf -
[ -f "$tree/src/gpm/studies/define/registry.cpp" ] || fail "the copy has no registry.cpp"
[ ! -e "$tree/src/apps/$name.cpp" ] || fail "the tree already has src/apps/$name.cpp"

# --- the study: its unit body ---------------------------------------------------------------
cat > "$tree/src/apps/$name.cpp" <<'EOF'
// scratch_interpolant: a throwaway study (tests/registry/add_study_test.sh) -- the quartic
// interpolant of sin 2pi(x+y) on the plain grid, h = 3.1 dx, one fused pass per level.
#include <cmath>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"

using namespace gpm;

namespace {

class ScratchInterpolant {
 public:
  ScratchInterpolant(int argc, char** argv)
      : run_(study_registry().study("scratch_interpolant"), "A throwaway study: the interpolant on the plain grid.") {
    run_.parse(argc, argv);
  }

  int run() {
    UnitCache& cache = run_.open({{"program", "scratch_interpolant"}, {"seed", "1"}}, 2);
    for (const StudyUnit& u : run_.units())
      if (!cache.has(u.key) && run_.claim()) pass(u);
    run_.finish();
    return 0;
  }

 private:
  // One unit: the level's fused pass.
  void pass(const StudyUnit& u) {
    const Particles p = jittered_grid(std::ldexp(1.0, -u.level), 1, 0.0);
    const FusedErrors e = fused_errors(p, uniform_volumes(p), u.h, {{"quartic_polynomial", Operator::interp}}, {"sin2pi"});
    TsvRow row = run_.row();
    row["weight"] = "quartic_polynomial", row["level"] = fmt(u.level), row["h"] = fmt(u.h);
    row["rel_error"] = fmt(e.errors.at(0).rel_error), row["pairs"] = fmt(e.pairs), row["time_s"] = fmt(e.kernel_seconds);
    run_.add(row);
    run_.unit_done(0, "level " + fmt(u.level));
  }

  StudyRunner run_;
};

int body(int argc, char** argv) { return ScratchInterpolant(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("scratch_interpolant", body, argc, argv); }
EOF

# --- the study: its registry entry, and the registry's list gets it --------------------------
entry=$(cat <<'EOF'
// A throwaway study (tests/registry/add_study_test.sh): levels, columns, units and price.
static RegisteredStudy scratch_study() {
  RegisteredStudy s;
  s.name = s.program = "scratch_interpolant";
  s.item = "scratch: the interpolant on the plain grid";
  s.group = "scratch";
  s.levels = {{4, 5}, {4, 5, 6}};
  s.columns = {"weight", "level", "h", "rel_error", "pairs", "time_s"};
  s.recheck_levels = {4};
  s.files = {{.name = "scratch_interpolant"}};
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> u;
    for (int k : scope.levels) u.push_back({k, 3.1 * std::ldexp(1.0, -k), {"quartic_polynomial", fmt(k)}, "quartic"});
    return u;
  };
  s.price = [](UnitPricer& p, const StudyUnit& u) { p.add_fused("scratch_interpolant", u.variant, u.level, u.h, "imoto9"); };
  return s;
}

EOF
)
reg=$tree/src/gpm/studies/define/registry.cpp
awk -v entry="$entry" '
  /^const StudyRegistry& study_registry\(\) \{/ { print entry; inside = 1 }
  inside && /^    return v;/ { print "    v.add(scratch_study());"; inside = 0; added = 1 }
  { print }
  END { if (!added) exit 3 }' "$reg" > "$reg.new" || fail "registry.cpp: no 'study_registry()' list ending in 'return v;' to add the entry to"
sed -i 's|^#include "gpm/studies/define/registry_books.hpp"|&\n#include "gpm/studies/define/pricing.hpp"|' "$reg.new"
mv "$reg.new" "$reg"
grep -q 'v.add(scratch_study());' "$reg" || fail "the entry was not added"

# --- the copy's build: configure as this build, share its compiler cache ---------------------
cache_of() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
cfg=(-DCMAKE_BUILD_TYPE="$(cache_of CMAKE_BUILD_TYPE)" -DGPM_NATIVE="$(cache_of GPM_NATIVE)")
[ -n "$(cache_of GPM_CCACHE_DIR)" ] && cfg+=(-DGPM_CCACHE_DIR="$(cache_of GPM_CCACHE_DIR)")
t0=$(date +%s)
cmake -S "$tree" -B "$tree/build" "${cfg[@]}" >"$work/configure.log" 2>&1 || { tail -20 "$work/configure.log"; fail "the copy does not configure"; }
cmake --build "$tree/build" -j "$(nproc)" --target gpm plan "$name" >"$work/build.log" 2>&1 \
  || { grep -E 'error|Error' "$work/build.log" | head -20; fail "the copy with the study does not build"; }
objects=$(grep -c 'Building CXX object' "$work/build.log" || true)
echo "add_study_test: the copy built (gpm, plan, $name) in $(( $(date +%s) - t0 )) s, $objects objects (from the cache where it hits)"
b=$tree/build

# --- the catalog lists it, make gets its rules ------------------------------------------------
# (outputs go to files before grep -q reads them: under pipefail a grep that stops early would
# fail the pipeline with the writer's SIGPIPE)
"$b/gpm" study --list >"$work/list.tsv"
grep -q "^$name\b" "$work/list.tsv" || fail "gpm study --list does not list $name"
"$b/gpm" study --make "$b/studies.mk"
grep -qF "\$(DATA)/$name.tsv: \$(BUILD)/$name" "$b/studies.mk" || fail "build/studies.mk has no data rule for $name"
grep -qE "^STUDIES_scratch := $name\$" "$b/studies.mk" || fail "build/studies.mk has no group list STUDIES_scratch"

# --- make runs it by that rule, a rerun reuses every unit, gpm study runs it by name ---------
make -C "$tree" BUILD=build "data/quick/$name.tsv" >"$work/make.log" 2>&1 || { tail -20 "$work/make.log"; fail "make data/quick/$name.tsv fails"; }
data=$tree/data/quick/$name.tsv
[ "$(grep -vc '^#' "$data")" -eq 3 ] || fail "data/quick/$name.tsv: not a header and the quick profile's 2 levels"
for k in program seed git_revision; do grep -q "^# $k = " "$data" || fail "data/quick/$name.tsv: no '# $k' line"; done
"$b/$name" --profile quick --out "$data" >"$work/rerun.log" 2>&1 || { cat "$work/rerun.log"; fail "the rerun fails"; }
grep -q 'reusing 2 stored rows' "$work/rerun.log" || { cat "$work/rerun.log"; fail "a rerun does not reuse the 2 stored rows"; }
"$b/gpm" study "$name" --levels 4,5,6 --out "$data" >/dev/null 2>&1 || fail "gpm study $name does not run"
[ "$(grep -vc '^#' "$data")" -eq 4 ] || fail "gpm study $name --levels 4,5,6 did not add level 6"

# --- the plan prices its units ----------------------------------------------------------------
"$b/plan" --profile paper --out "$work/plan.tsv" >/dev/null 2>&1 || fail "plan fails in the copy"
n=$(awk -F'\t' -v s="$name" '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next } $c["study"] == s' "$work/plan.tsv" | wc -l)
[ "$n" -eq 3 ] || fail "the plan prices $n units of $name, not its 3 paper levels"

# --- the layer and fingerprint rules hold in the copy ----------------------------------------
bash "$tree/tests/layers/check_layers_test.sh" "$tree" >"$work/layers.log" 2>&1 || { tail "$work/layers.log"; fail "the layer rule fails in the copy"; }
"$b/gpm" fingerprint "$name" >"$work/fingerprint.tsv"
grep -qE "^$name[[:space:]]+[0-9a-f]{12}$" "$work/fingerprint.tsv" || fail "$name has no code fingerprint"
# What the registry edit costs the store: every program hashes registry.cpp (the studies'
# definitions), so the fingerprints it moves are told, to be carried by the store's re-check.
moved=$(join -t $'\t' <("$build/gpm" fingerprint thesis_table4_4 thesis_heat core_voronoi | sort) \
                      <("$b/gpm" fingerprint thesis_table4_4 thesis_heat core_voronoi | sort) | awk -F'\t' '$2 != $3' | wc -l)
echo "add_study_test: $name added by its two files: built, listed, given make rules, run by make and by name, cached, priced; the registry edit moves $moved of 3 sampled study fingerprints (the store's re-check carries their rows)"
