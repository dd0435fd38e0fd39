#!/bin/bash
# The paper profile on a Slurm cluster: one array task per catalog study (gpm study --list),
# each on RANKS MPI ranks; the rows land in the result store results/paper/ (rank 0 writes,
# holding the file's lock), where `make report` reads them.  Build once with MPI first:
#   cmake -S . -B build-mpi -DGPM_MPI=ON && cmake --build build-mpi -j
#   sbatch --array=0-7 bench/slurm_paper.sh            (8 studies; core_voronoi runs alone)
# Size the time limit from `make plan PROFILE=paper` (it prints the time on P processes): an MPI
# run writes its file when it ends, so a task cut by its limit keeps only the units of earlier
# runs.  A finished study's rerun computes nothing (its units are in the store).
#SBATCH --job-name=gpm-paper
#SBATCH --ntasks=8
#SBATCH --cpus-per-task=4
#SBATCH --time=04:00:00
#SBATCH --output=gpm-paper-%A_%a.log
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
BUILD=${BUILD:-build-mpi}
# The registry's studies in its order (gpm study --list, column "study"), core_voronoi aside.
mapfile -t studies < <("$BUILD/gpm" study --list | awk -F'\t' '
  /^#/ { next }
  !seen { for (i = 1; i <= NF; i++) col[$i] = i; seen = 1; next }
  $col["study"] != "core_voronoi" { print $col["study"] }')
name=${studies[${SLURM_ARRAY_TASK_ID:-0}]}
export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
echo "study $name on ${SLURM_NTASKS:-1} ranks x $OMP_NUM_THREADS threads, $(date -u +%FT%TZ)"
srun "$BUILD/gpm" study "$name" --profile paper --out "results/paper/$name.tsv"
