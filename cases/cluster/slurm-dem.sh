#!/usr/bin/env bash
# The wear tester in DEM at the study's own particle size (s = 1, about 1.7 million particles
# in the 150-degree sector) on a Slurm cluster: the bed cut into one angular slab per MPI
# rank, OpenMP threads inside each rank. Submit from the repository root after building:
#
#     sbatch cases/cluster/slurm-dem.sh                          # the plain sample
#     CASE=cases/scaling-factor/convex-s1.prm sbatch cases/cluster/slurm-dem.sh
#
# 16 ranks x 4 threads = 64 cores on 2 nodes here; see cases/cluster/README.md for choosing
# ranks and threads. `wearsim dem` keeps no checkpoint (over ranks not yet, issue 31): ask
# for enough time for the revolutions in DEM/Revolutions.
#SBATCH --job-name=wearsim-dem-s1
#SBATCH --nodes=2
#SBATCH --ntasks=16
#SBATCH --cpus-per-task=4
#SBATCH --time=1-00:00:00
#SBATCH --output=wearsim-dem-%j.log
set -euo pipefail
CASE=${CASE:-cases/scaling-factor/plain-s1.prm}
# One OpenMP thread per core given to the rank (DEM/Threads = 0 takes all the process sees;
# set DEM/Threads in the case to the same number to write it into parameters.prm).
export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
export OMP_PROC_BIND=close OMP_PLACES=cores
# Each rank's threads on its own cores.
mpirun -np "${SLURM_NTASKS}" --map-by "ppr:$((SLURM_NTASKS / SLURM_NNODES)):node:pe=${OMP_NUM_THREADS}" \
  build/wearsim dem "$CASE"
