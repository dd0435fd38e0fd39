#!/bin/bash
# check_layers.sh on the real core (must pass) and on a small tree with one upward include
# and one numerics-to-io include (must fail, naming both).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=${1:?usage: check_layers_test.sh SOURCE_DIR}
bash "$here/check_layers.sh" "$src/src/gpm" || { echo "FAIL: the core breaks its layers"; exit 1; }
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
mkdir -p "$t/geometry" "$t/solvers" "$t/io"
printf '#include "gpm/error.hpp"\n#include "gpm/solvers/heat.hpp"\n' > "$t/geometry/domain.hpp"
printf '#include "gpm/io/tsv.hpp"\n#include "gpm/geometry/domain.hpp"\n' > "$t/solvers/heat.hpp"
printf '#include "gpm/io/args.hpp"\n' > "$t/io/tsv.hpp"
out=$(bash "$here/check_layers.sh" "$t") && { echo "FAIL: a tree with violations passed"; exit 1; }
for want in "geometry/domain.hpp (geometry) includes gpm/solvers/heat.hpp" \
            "solvers/heat.hpp (solvers) includes gpm/io/tsv.hpp" "2 violations"; do
  grep -qF "$want" <<<"$out" || { echo "FAIL: expected '$want' in:"; echo "$out"; exit 1; }
done
echo "check_layers_test: the core passes, the bad tree is rejected on both counts"
