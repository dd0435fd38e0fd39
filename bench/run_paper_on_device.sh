#!/usr/bin/env bash
# The paper profile on a GPU (issue 15, item 2), for a session or a machine with one:
# configure and build a -DGPM_CUDA=ON tree, then run every catalog study with --device cuda
# (truncation passes: the device's fused pass; Poisson/heat: matrix-free products on the
# device, conjugate gradients on the host).
#
#   bash bench/run_paper_on_device.sh verify [LEVELS]   (default)
#       recompute the committed store's units on the device and compare them with the CPU
#       rows (--verify: numbers to 1e-9 relative); nothing is written to the store.
#       LEVELS (e.g. 5,6,7) limits every study to those levels.
#   bash bench/run_paper_on_device.sh run
#       compute the paper profile into $OUT/device/ (or data/device/), one data file per
#       study as the CPU programs write them (their made_on column says "device cuda");
#       copy a file into results/paper/ only after `verify` agreed.
#
# First bench_cuda: the device's measured fp64 peak and each study's pass (all its weights and
# test functions) in pairs/s and as a fraction of that peak, checked against the CPU
# ($OUT/device/cuda.tsv).  Each study then has its own timeout (STUDY_TIMEOUT, default 600 s),
# so one slow study leaves the others' results; the logs go to $OUT (or the build dir).
# Environment: BUILD (default build-cuda-paper), GPM_CUDA_ARCH (default 90), JOBS, REUSE=1;
# PREBUILT=DIR: DIR already holds bench_cuda, gpm and the study programs (built elsewhere with
# -DGPM_CUDA=ON, as bench/pack_device_build.sh packs them for a machine without the
# libraries): nothing is configured or built; LEVELS_<study>=A,B: that study's levels
# (overrides LEVELS, e.g. LEVELS_thesis_table4_4=6,7).
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -uo pipefail
cd "$(dirname "$0")/.."
mode=${1:-verify}
levels=${2:-}
case $mode in verify|run) ;; *) echo "run_paper_on_device.sh: unknown mode '$mode' (verify or run)" >&2; exit 2;; esac
BUILD=${BUILD:-build-cuda-paper}
ARCH=${GPM_CUDA_ARCH:-90}
JOBS=${JOBS:-$(nproc)}
LOGS=${OUT:-$BUILD}
DEST=${OUT:-data}/device
STUDY_TIMEOUT=${STUDY_TIMEOUT:-600}
mkdir -p "$LOGS" "$DEST"
t0=$(date +%s)
step() { echo "[run_paper_on_device $(( $(date +%s) - t0 )) s] $*"; }

command -v nvidia-smi > /dev/null && nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv || true
if [ -n "${PREBUILT:-}" ]; then
  BUILD=$PREBUILT
  step "prebuilt programs in $BUILD (nothing configured or built)"
else
  [ "${REUSE:-0}" = 1 ] || rm -rf "$BUILD"
  step "configure and build $BUILD (GPM_CUDA=ON, architecture $ARCH, $JOBS jobs)"
  if ! timeout 240 cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DGPM_CUDA=ON \
      -DCMAKE_CUDA_ARCHITECTURES="$ARCH" > "$LOGS/device_configure.log" 2>&1 ||
     ! timeout 900 cmake --build "$BUILD" -j"$JOBS" > "$LOGS/device_build.log" 2>&1; then
    tail -20 "$LOGS/device_configure.log" "$LOGS/device_build.log" 2>/dev/null
    step "configure/build FAILED"
    exit 1
  fi
fi

step "bench_cuda (fp64 peak, the studies' passes against the CPU)"
timeout 300 "$BUILD/bench_cuda" --out "$DEST/cuda.tsv" 2>&1 | tee "$LOGS/device_bench.log" | tail -12

# The registry's studies (gpm study --list: the study, which names its store file, and its
# program with the fixed arguments), core_voronoi aside (no device pass); the store files
# read are the h10 reading with the documents' volumes, the ones the scoreboard counts first.
# A program with --storage (the PDE studies) runs its Laplacian matrix-free, so that every
# product is on the device.
studies=()
while IFS=$'\t' read -r study program; do
  # core_voronoi has no device pass; thesis_poisson_diagnostic assembles its Laplacians on
  # the host (and loops its own variants, not the registry's units: issue 57, item 3).
  case $study in core_voronoi|thesis_poisson_diagnostic) continue;; esac
  storage=""
  "$BUILD/${program%% *}" --help 2>/dev/null | grep -qE '^  --storage( |$)' && storage=" --storage matrix_free"
  studies+=("$study.tsv $program$storage")
done < <("$BUILD/gpm" study --list | awk -F'\t' -v OFS='\t' '
  /^#/ { next }
  !seen { for (i = 1; i <= NF; i++) col[$i] = i; seen = 1; next }
  { print $col["study"], $col["program"] }')
failed=0
for s in "${studies[@]}"; do
  read -r file prog args <<< "$s"
  own=LEVELS_${file%.tsv}
  lv=()
  if [ -n "${!own:-}" ]; then lv=(--levels "${!own}")
  elif [ -n "$levels" ]; then lv=(--levels "$levels"); fi
  if [ "$mode" = verify ]; then
    out=(--out "results/paper/$file" --verify)
  else
    out=(--out "$DEST/$file")
  fi
  step "$prog $args ${lv[*]} --device cuda ${out[*]}"
  # shellcheck disable=SC2086
  timeout "$STUDY_TIMEOUT" "$BUILD/$prog" $args --profile paper --device cuda "${lv[@]}" \
    "${out[@]}" > "$LOGS/device_${file%.tsv}.log" 2>&1
  rc=$?
  grep -E '\[store\]|error' "$LOGS/device_${file%.tsv}.log" | tail -4
  [ $rc -eq 0 ] || { failed=$((failed + 1)); step "  exit $rc (124: timed out)"; }
done
step "done: $failed of ${#studies[@]} studies failed or timed out (logs in $LOGS)"
[ $failed -eq 0 ]
