#!/usr/bin/env bash
# Packs a -DGPM_CUDA=ON build made here for a GPU machine that has CUDA's driver and compiler
# but none of the project's libraries (Eigen, CGAL, GSL, GMP: the device image), so that
# bench/run_paper_on_device.sh runs there with PREBUILT=DIR and nothing is built on the
# device's clock.
#
#   bash bench/pack_device_build.sh [BUILD] [DIR]     (defaults: build-cuda, devbin)
#
# BUILD must have been configured portably, since the device's CPU is not this one:
#   cmake -S . -B build-cuda -DCMAKE_BUILD_TYPE=Release -DGPM_CUDA=ON \
#     -DCMAKE_CUDA_ARCHITECTURES=90 -DGPM_NATIVE=OFF -DCMAKE_CXX_FLAGS=-march=x86-64-v3
# DIR gets, per program, a wrapper DIR/NAME that runs DIR/real/NAME with the shared
# libraries of DIR/lib (GSL, GMP, OpenMP).  Where the device's C library is older than this
# machine's, `export GPM_LOADER=1` makes the wrappers start the programs through this
# machine's loader and C++/C libraries (DIR/lib-full) instead.  GPM_SOURCE_DIR is compiled
# in as this checkout's path: on the device, link that path to the copy of the tree.
export LC_ALL=C
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build-cuda}
DIR=${2:-devbin}
programs=(bench_cuda gpm)
# The programs of the study registry (gpm study --list), as the device script runs them.
while read -r p; do programs+=("$p"); done < <("$BUILD/gpm" study --list | awk -F'\t' '
  /^#/ { next }
  !seen { for (i = 1; i <= NF; i++) col[$i] = i; seen = 1; next }
  { split($col["program"], w, " "); print w[1] }' | sort -u)
rm -rf "$DIR"
mkdir -p "$DIR/real" "$DIR/lib" "$DIR/lib-full"
for p in "${programs[@]}"; do
  [ -x "$BUILD/$p" ] || { echo "pack_device_build: $BUILD/$p is missing (build it first)" >&2; exit 1; }
  strip -o "$DIR/real/$p" "$BUILD/$p"
  cat > "$DIR/$p" <<EOF
#!/bin/sh
d=\$(dirname "\$0")
if [ -n "\${GPM_LOADER:-}" ]; then
  exec "\$d/lib-full/ld-linux-x86-64.so.2" --library-path "\$d/lib-full" "\$d/real/$p" "\$@"
fi
LD_LIBRARY_PATH="\$d/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" exec "\$d/real/$p" "\$@"
EOF
  chmod +x "$DIR/$p"
done
# Every shared library the programs load, resolved here; the project's own (GSL, GMP,
# OpenMP) in lib/, all of them with the loader in lib-full/.
ldd "${programs[@]/#/$BUILD/}" | awk '$2 == "=>" && $3 ~ /^\// { print $3 } $1 ~ /^\/.*ld-linux/ { print $1 }' |
  sort -u | while read -r so; do
    cp -L "$so" "$DIR/lib-full/"
    case $(basename "$so") in libgsl*|libgmp*|libgomp*) cp -L "$so" "$DIR/lib/";; esac
  done
pwd > "$DIR/source_dir"  # GPM_SOURCE_DIR, for the device to link to its copy of the tree
echo "pack_device_build: ${#programs[@]} programs in $DIR ($(du -sh "$DIR" | cut -f1))"
