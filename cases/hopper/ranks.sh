#!/usr/bin/env bash
# The hopper over MPI ranks (cases/hopper/README.md, "Over ranks"): hopper.prm for seeds 1 to
# N (default 4) as one process on 2 threads and on 2 and 4 ranks of one thread each (4 ranks
# share 2 cores here: --oversubscribe), without particle snapshots. Writes a case file per
# run into output/hopper-ranks/cases/ and each run into output/hopper-ranks/r<ranks>-s<seed>;
# a run whose folder holds a finished series is skipped, so the script resumes a study.
# Then: /usr/bin/python3 cases/hopper/ranks_report.py
#   usage: [WEARSIM=path/to/wearsim] [MPIRUN="mpirun --allow-run-as-root"] \
#          bash cases/hopper/ranks.sh [N]
set -euo pipefail
cd "$(dirname "$0")/../.."
n_seeds=${1:-4}
out=output/hopper-ranks
mpirun=${MPIRUN:-mpirun}
mkdir -p "$out/cases"
for seed in $(seq 1 "$n_seeds"); do
  for ranks in 1 2 4; do
    run="r$ranks-s$seed"
    if [ -f "$out/$run/scene_series.csv" ] &&
       awk -F, 'NR > 1 { t = $1 } END { exit !(t >= 1.2 - 1e-6) }' "$out/$run/scene_series.csv"; then
      continue
    fi
    threads=$([ "$ranks" = 1 ] && echo 2 || echo 1)
    prm="$out/cases/$run.prm"
    cat > "$prm.tmp" <<PRM
INCLUDE cases/hopper/hopper.prm
subsection Scene
  set Particle snapshots = false
end
subsection DEM
  set Seed = $seed
  set Threads = $threads
end
subsection Output
  set Directory = $out/$run
end
PRM
    mv "$prm.tmp" "$prm"
    echo "run $run ($(date -u +%H:%M:%S))"
    if [ "$ranks" = 1 ]; then
      "${WEARSIM:-build/wearsim}" scene-run --overwrite "$prm" > "$out/$run.log" 2>&1
    else
      OMPI_MCA_mpi_yield_when_idle=1 $mpirun --oversubscribe -np "$ranks" \
        "${WEARSIM:-build/wearsim}" scene-run --overwrite "$prm" > "$out/$run.log" 2>&1
    fi
  done
done
