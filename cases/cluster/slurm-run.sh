#!/usr/bin/env bash
# The coupled DEM-FEM run (`wearsim run`) at the study's own particle size (s = 1) on a Slurm
# cluster: the DEM over one angular slab per MPI rank with OpenMP threads inside each rank, the
# FEM stage on every rank between the windows. Submit from the repository root after
# building; submit the same command again to continue a run that reached its time limit:
#
#     sbatch cases/cluster/slurm-run.sh                          # the plain sample
#     CASE=cases/scaling-factor/convex-s1.prm sbatch cases/cluster/slurm-run.sh
#     COMMAND=dem sbatch cases/cluster/slurm-run.sh                       # the DEM alone
#     COMMAND=scene-run CASE=cases/chute/chute.prm sbatch cases/cluster/slurm-run.sh   # a scene
#
# Slurm sends SIGUSR1 to mpirun 5 minutes before the time limit (--signal=B:USR1@300); mpirun
# passes it to the ranks, which stop together at the end of the current window (a tester
# case's: a revolution over DEM/Samples per revolution; it must take less than the 5
# minutes), write their parts of the checkpoint and exit. The next submission resumes there (--resume), on as many ranks as it is given: the
# same count continues bit for bit, another count re-cuts the bed (docs/user-guide.md, "On
# several processes (MPI)"). Output/Checkpoint interval bounds what a hard kill loses.
#SBATCH --job-name=wearsim-run-s1
#SBATCH --nodes=2
#SBATCH --ntasks=16
#SBATCH --cpus-per-task=4
#SBATCH --time=1-00:00:00
#SBATCH --signal=B:USR1@300
#SBATCH --output=wearsim-run-%j.log
set -euo pipefail
CASE=${CASE:-cases/scaling-factor/plain-s1.prm}
COMMAND=${COMMAND:-run} # run: the coupled run; dem: a tester case's DEM alone; scene-run
export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
export OMP_PROC_BIND=close OMP_PLACES=cores
# A folder holding this case's checkpoint continues; otherwise the run starts.
dir=$(sed -n 's/^ *set Directory *= *//p' "$CASE" | tail -1)
mode=
[ -n "$dir" ] && [ -f "$dir/checkpoint.h5" ] && mode=--resume
# exec: mpirun receives Slurm's signal itself and passes it to the ranks.
exec mpirun -np "${SLURM_NTASKS}" \
  --map-by "ppr:$((SLURM_NTASKS / SLURM_NNODES)):node:pe=${OMP_NUM_THREADS}" \
  build/wearsim "$COMMAND" $mode "$CASE"
