#!/usr/bin/env bash
# Back-to-back DEM performance comparison with the LIGGGHTS anchor (shared/anchors/liggghts).
# Runs, in one time window: our annulus workload (1 and 2 threads, interleaved repeats), the
# anchor's annulus45k (1 and 2 MPI ranks), and our sector workloads 5k/20k/45k (2 threads)
# for the cost-per-particle-step scaling. Raw logs go to $OUT (default /tmp/wear-bench).
# usage: bash scripts/bench_vs_liggghts.sh [repeats]     (about 15 min with 3 repeats)
set -euo pipefail
cd "$(dirname "$0")/.."
R=${1:-3}
OUT=${OUT:-/tmp/wear-bench}
mkdir -p "$OUT"
ANCHOR=$(realpath ../shared/anchors/liggghts)
LIG=$OUT/liggghts
if [ ! -f "$LIG/restarts/annulus45k.restart" ]; then
  rm -rf "$LIG" && cp -r "$ANCHOR" "$LIG"
  (cd "$LIG" && TMO=900 STAGE=setup ONLY="annulus45k" ./run.sh) > "$OUT/liggghts_setup.log" 2>&1
fi
echo "== ours: annulus, 24000 settling steps, 3 x 5000 timed steps per thread count"
./build/wearsim bench dem --workload annulus --threads 1,2 --settle 24000 --warm 500 \
  --steps 5000 --repeats "$R" | tee "$OUT/ours_annulus.log"
echo "== LIGGGHTS 3.8: annulus45k, 1 and 2 ranks"
(cd "$LIG" && TMO=900 STAGE=bench ONLY="annulus45k" REPEATS_EXTRA="$R" ./run.sh) | tee "$OUT/liggghts_bench.log"
for w in sector5k sector20k sector45k; do
  echo "== ours: $w"
  steps=$([ $w = sector5k ] && echo 20000 || ([ $w = sector20k ] && echo 10000 || echo 5000))
  ./build/wearsim bench dem --workload $w --threads 2 --settle 24000 --warm 500 \
    --steps "$steps" --repeats "$R" | tee "$OUT/ours_$w.log"
done
grep -h "Loop time" "$LIG"/logs/bench_annulus45k_np*_r*.log | tee "$OUT/liggghts_loop_times.txt"
