#!/usr/bin/env bash
# One device session's check of the GPU path, as a single command on the device machine
# (its time is short: about 15 minutes a session, machine start included).  Run here first:
#   bash bench/pack_device_build.sh build-cuda devbin      (programs built here, see there)
# then on the device, from the tree's root, with devbin carried:
#   bash bench/device_verify_session.sh
# 1. run_paper_on_device.sh verify with the prebuilt programs, each study at levels that take
#    seconds on a CPU (the device's matrix-free products and fused passes against the stored
#    CPU rows, to kStoreRelTol);
# 2. the same units once more with --device cpu on the same machine, for the wall times side
#    by side (the CPU column of the comparison, same machine, same run);
# 3. the logs packed into $OUT/logs.tgz (the device returns at most 8 files).
export LC_ALL=C
set -uo pipefail
cd "$(dirname "$0")/.."
OUT=${OUT:-data/device-session}
mkdir -p "$OUT"
exec > >(tee "$OUT/session.log") 2>&1  # the steps with their levels travel with the logs
# GPM_SOURCE_DIR was compiled in as the packing checkout's path.
src=$(cat devbin/source_dir)
[ -e "$src" ] || { mkdir -p "$(dirname "$src")" && ln -s "$PWD" "$src"; }
devbin/gpm --help > /dev/null 2>&1 || { export GPM_LOADER=1; echo "device_verify_session: the bundled loader and C library"; }
echo "host: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
export PREBUILT=devbin STUDY_TIMEOUT=${STUDY_TIMEOUT:-75}
export LEVELS_imoto_fig5_table1=8,9 LEVELS_thesis_table4_1=8 LEVELS_thesis_table4_2=8,9
export LEVELS_thesis_table4_3=8 LEVELS_thesis_table4_4=6,7
timeout 400 bash bench/run_paper_on_device.sh verify 5
echo "device_verify_session: the same units on this machine's CPU"
while read -r file levels prog; do
  t0=$(date +%s%N)
  # shellcheck disable=SC2086
  timeout 90 devbin/$prog --profile paper --levels "$levels" --device cpu \
    --out "results/paper/$file.tsv" --verify > "$OUT/cpu_$file.log" 2>&1
  echo "cpu $file levels $levels: exit $? in $(( ($(date +%s%N) - t0) / 1000000 )) ms"
  grep '\[store\]' "$OUT/cpu_$file.log" | head -1
done <<'LIST'
imoto_fig5_table1 8,9 imoto_fig5_table1
thesis_table4_2 8,9 thesis_table4_2
thesis_table4_3 8 thesis_table4_3
thesis_table4_4 6,7 thesis_table4_4 --storage matrix_free
thesis_table4_5 5 thesis_heat --table 4.5 --storage matrix_free
LIST
(cd "$OUT" && tar czf logs.tgz ./*.log && rm -f ./*.log)
