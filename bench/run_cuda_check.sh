#!/usr/bin/env bash
# The GPU check of issue 7, item 5, in one go (for a session that has a GPU machine):
# configure a fresh build with -DGPM_CUDA=ON, build bench_cuda, run it, and copy its table
# (data/bench/cuda.tsv) and the logs to $OUT when that is set.
#
#   bash bench/run_cuda_check.sh [bench_cuda options...]
#
# Budget: about 10 minutes in all.  The build compiles gpm_core from scratch (CGAL's
# voronoi.cpp is the longest file, ~1–2 min with enough cores) and the CUDA file for one
# GPU generation only (GPM_CUDA_ARCH, default 90 = H100/H200; 80 for A100); bench_cuda
# itself takes well under a minute on an H100-class GPU.  Each step has its own timeout so
# a hang still leaves the logs.
# Environment: BUILD (build dir, default build-cuda-check), GPM_CUDA_ARCH, JOBS, REUSE=1
# (keep an existing build dir instead of starting fresh).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -uo pipefail
cd "$(dirname "$0")/.."

BUILD=${BUILD:-build-cuda-check}
ARCH=${GPM_CUDA_ARCH:-90}
JOBS=${JOBS:-$(nproc)}
LOGS=${OUT:-$BUILD}
mkdir -p "$LOGS" data/bench
TSV=data/bench/cuda.tsv
t0=$(date +%s)
step() { echo "[run_cuda_check $(( $(date +%s) - t0 )) s] $*"; }

if command -v nvidia-smi > /dev/null; then
  nvidia-smi --query-gpu=name,memory.total,driver_version,compute_cap --format=csv || true
else
  step "nvidia-smi not found (bench_cuda will say whether a device is usable)"
fi

# The include line in CMakeLists.txt, or the same file injected right after project().
extra=()
if ! grep -q '^include(cmake/cuda.cmake)' CMakeLists.txt; then
  extra=(-DCMAKE_PROJECT_INCLUDE="$PWD/cmake/cuda.cmake")
  step "CMakeLists.txt has no include(cmake/cuda.cmake): injecting it with CMAKE_PROJECT_INCLUDE"
fi

step "configure $BUILD (GPM_CUDA=ON, CUDA architecture $ARCH)"
[ "${REUSE:-0}" = 1 ] || rm -rf "$BUILD"  # REUSE=1: keep an existing build (testing)
if ! timeout 180 cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DGPM_CUDA=ON \
    -DCMAKE_CUDA_ARCHITECTURES="$ARCH" "${extra[@]}" > "$LOGS/cuda_configure.log" 2>&1; then
  tail -20 "$LOGS/cuda_configure.log"
  step "configure FAILED (log: $LOGS/cuda_configure.log)"
  exit 1
fi

step "build bench_cuda with $JOBS jobs"
if ! timeout 420 cmake --build "$BUILD" -j"$JOBS" --target bench_cuda > "$LOGS/cuda_build.log" 2>&1; then
  tail -30 "$LOGS/cuda_build.log"
  step "build FAILED (log: $LOGS/cuda_build.log)"
  exit 1
fi
grep -i "warning" "$LOGS/cuda_build.log" | grep -i "cuda" | head -5 || true

step "run bench_cuda"
rm -f "$TSV"
rc=0
timeout 240 "$BUILD/bench_cuda" --out "$TSV" "$@" 2>&1 | tee "$LOGS/cuda_bench.log" || rc=$?

if [ -n "${OUT:-}" ] && [ -f "$TSV" ]; then
  cp "$TSV" "$OUT/cuda.tsv"
  step "copied $TSV to $OUT/cuda.tsv"
fi
step "done (bench_cuda exit code $rc)"
exit "$rc"
