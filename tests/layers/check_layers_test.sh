#!/bin/bash
# check_layers.sh on the real core (must pass) and on a small tree with one upward include,
# one numerics-to-io include, a judgement that includes the store, a definition that
# includes the plan and a file in no room of studies/ (must fail, naming each).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=${1:?usage: check_layers_test.sh SOURCE_DIR}
bash "$here/check_layers.sh" "$src/src/gpm" || { echo "FAIL: the core breaks its layers"; exit 1; }
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/geometry" "$t/solvers" "$t/io" "$t/studies/judge" "$t/studies/define" "$t/studies/run"
printf '#include "gpm/error.hpp"\n#include "gpm/solvers/heat.hpp"\n' > "$t/geometry/domain.hpp"
printf '#include "gpm/io/tsv.hpp"\n#include "gpm/geometry/domain.hpp"\n' > "$t/solvers/heat.hpp"
printf '#include "gpm/io/args.hpp"\n' > "$t/io/tsv.hpp"
printf '#include "gpm/studies/define/registry.hpp"\n#include "gpm/studies/run/store.hpp"\n' > "$t/studies/judge/rates.hpp"
printf '#include "gpm/solvers/heat.hpp"\n#include "gpm/studies/plan/study_plan.hpp"\n' > "$t/studies/define/registry.hpp"
printf '#include "gpm/studies/define/registry.hpp"\n' > "$t/studies/run/store.hpp"
printf '#include "gpm/io/tsv.hpp"\n' > "$t/studies/loose.hpp"
out=$(bash "$here/check_layers.sh" "$t") && { echo "FAIL: a tree with violations passed"; exit 1; }
for want in "geometry/domain.hpp (geometry) includes gpm/solvers/heat.hpp" \
            "solvers/heat.hpp (solvers) includes gpm/io/tsv.hpp" \
            "studies/judge/rates.hpp (studies/judge) includes gpm/studies/run/store.hpp (studies/run)" \
            "studies/define/registry.hpp (studies/define) includes gpm/studies/plan/study_plan.hpp (studies/plan)" \
            "studies/loose.hpp (studies) includes gpm/io/tsv.hpp" "5 violations"; do
  grep -qF "$want" <<<"$out" || { echo "FAIL: expected '$want' in:"; echo "$out"; exit 1; }
done
echo "check_layers_test: the core passes, the bad tree is rejected on all five counts"
