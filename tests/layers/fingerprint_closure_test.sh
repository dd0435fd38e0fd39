#!/bin/bash
# A program's code fingerprint covers its include closure (cmake/fingerprint.cmake), not the
# whole core: sound only if every object of the core library that the linker puts into the
# program comes from a source in that closure.  A source that implements a header it is not
# named after, and is reached by no include of the program, would decide numbers unseen; this
# test reads each program's link map (build/maps/NAME.map) and fails naming such an object.
# Every core source's file name must be unique (an archive member is named by it alone).
# usage: fingerprint_closure_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C
set -u
build=${1:?usage: fingerprint_closure_test.sh BUILD_DIR SOURCE_DIR}
src=${2:?usage: fingerprint_closure_test.sh BUILD_DIR SOURCE_DIR}
closure=$build/gen/fingerprint.cpp.closure
[ -s "$closure" ] || { echo "FAIL: $closure is missing or empty (built by cmake/fingerprint.cmake)"; exit 1; }
dups=$(find "$src/src/gpm" -name '*.cpp' -printf '%f\n' | sort | uniq -d)
[ -z "$dups" ] || { echo "FAIL: core sources share a file name (a link map cannot tell them apart): $dups"; exit 1; }
fail=0 checked=0 objects=0
for map in "$build"/maps/*.map; do
  [ -e "$map" ] || { echo "FAIL: no link map in $build/maps"; exit 1; }
  prog=$(basename "$map" .map)
  grep -q "^$prog	" "$closure" || { echo "FAIL: $prog has a link map but no closure"; fail=1; continue; }
  for member in $(grep -o 'libgpm_core\.a([^)]*\.cpp\.o)' "$map" | sed 's/.*(\(.*\)\.o)/\1/' | sort -u); do
    objects=$((objects + 1))
    [ "$member" = fingerprint.cpp ] && continue  # the generated fingerprints themselves
    path=$(cd "$src" && find src/gpm -name "$member" | head -1)
    [ -n "$path" ] || { echo "FAIL: $prog links $member, which is no core source"; fail=1; continue; }
    grep -qxF "$prog	$path" "$closure" ||
      { echo "FAIL: $prog is built from $path, outside its fingerprint's closure"; fail=1; }
  done
  checked=$((checked + 1))
done
[ $checked -gt 0 ] || { echo "FAIL: no program checked"; exit 1; }
[ $fail -eq 0 ] && echo "fingerprint closure: $checked programs, each of their linked core objects ($objects in all) in their closure"
exit $fail
