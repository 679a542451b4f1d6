#!/usr/bin/env bash
# The DEM over MPI ranks against threads and against LIGGGHTS, back to back in one window
# (issue 31): per round, our annulus on 1 rank x 1 and 2 threads and on 2 ranks x 1 thread, and
# LIGGGHTS 3.8 on the anchor's annulus45k with 2 ranks (the same 5000 timed steps); then
# our sector45k on 4 ranks x 1 thread (oversubscribed on 2 cores), 2 ranks and 1 rank x 2
# threads, for the per-rank imbalance, ghosts and traffic the scaling model takes
# (scripts/scaling_model.py); last the wear tester at s = 3 on one thread, the model's compute
# per particle-step. Raw logs go to $OUT (default /tmp/wear-bench-mpi).
# usage: bash scripts/bench_mpi.sh [rounds]     (about 16 min with 3 rounds on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
R=${1:-3}
OUT=${OUT:-/tmp/wear-bench-mpi}
mkdir -p "$OUT"
exec > >(tee "$OUT/run.log") 2>&1
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)
export OMPI_MCA_mpi_yield_when_idle=1 # ranks sharing a core give it up while they wait
ANCHOR=$(realpath ../shared/anchors/liggghts)
LIG=${LIG_DIR:-/tmp/wear-bench/liggghts}
if [ ! -f "$LIG/restarts/annulus45k.restart" ]; then
  rm -rf "$LIG" && mkdir -p "$(dirname "$LIG")" && cp -r "$ANCHOR" "$LIG"
  (cd "$LIG" && TMO=1800 STAGE=setup ONLY="annulus45k" ./run.sh) > "$OUT/liggghts_setup.log" 2>&1
fi
ours=(build/wearsim bench dem --settle 24000 --warm 500 --steps 5000 --repeats 1)
echo "== $(date -u +%FT%TZ) $(build/wearsim --version), $R rounds, $(nproc) cores"
for r in $(seq 1 "$R"); do
  echo "== round $r: ours, annulus, 1 rank x 1 and 2 threads"
  "${ours[@]}" --workload annulus --threads 1,2 > "$OUT/ours_annulus_np1_t2_r$r.log"
  grep particle_steps_per_second "$OUT/ours_annulus_np1_t2_r$r.log"
  echo "== round $r: ours, annulus, 2 ranks x 1 thread"
  "${MPIRUN[@]}" -np 2 "${ours[@]}" --workload annulus --threads 1 > "$OUT/ours_annulus_np2_t1_r$r.log"
  grep particle_steps_per_second "$OUT/ours_annulus_np2_t1_r$r.log"
  echo "== round $r: LIGGGHTS 3.8, annulus45k, 2 ranks"
  (cd "$LIG" && "${MPIRUN[@]}" -np 2 liggghts -in in.bench -var case an_mono_45k -var walls annulus \
    -var rf cdt -var restart restarts/annulus45k.restart -var px '*' -var py '*' -var nsteps 5000 \
    -var wdir out -var tag "annulus45k_np2_mpi_r$r" -log "$OUT/liggghts_annulus45k_np2_r$r.log" \
    -echo none < /dev/null > /dev/null 2>&1)
  grep "Loop time" "$OUT/liggghts_annulus45k_np2_r$r.log"
done
for np in 4 2 1; do
  th=$((np == 1 ? 2 : 1))
  echo "== ours, sector45k, $np ranks x $th threads"
  "${MPIRUN[@]}" -np "$np" "${ours[@]}" --workload sector45k --threads "$th" \
    > "$OUT/ours_sector45k_np${np}_t$th.log"
  grep particle_steps_per_second "$OUT/ours_sector45k_np${np}_t$th.log"
done
echo "== ours, the wear tester at s = 3 (plain sample), 1 rank x 1 thread: the compute per particle-step"
build/wearsim bench dem --workload tester --scale 3 --sample plain --threads 1 --flow 3000 \
  --warm 200 --steps 3000 > "$OUT/ours_tester_s3_t1.log"
grep particle_steps_per_second "$OUT/ours_tester_s3_t1.log"
echo "== $(date -u +%FT%TZ) done; logs in $OUT"
