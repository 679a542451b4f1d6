#!/bin/bash
# The quick case over several insertion seeds, plain and convex: the default case's answer.
# One run of the 30-degree sector lands in a slow or a fast bed (the bed's slip over the
# sample is intermittent), so one run's wear per revolution moves by a factor of about two
# with the seed; the ensemble's mean does not. Each run uses one thread (DEM/Threads = 1 in
# the case files) and as many runs go at once as the machine has cores, so the results do
# not depend on the machine. Then `wearsim compare` prints every figure of the two sides as
# mean +- 95 % interval across the seeds, the comparison plot is drawn and
# cases/quick/report.py writes output/quick/report.md (with --update-readme also the
# README's figures and picture).
#
# usage: bash cases/quick/ensemble.sh [--update-readme] [seed ...]
#        (default seeds 1 2 3: about 4 min on 2 cores; JOBS=<n> sets the runs at once)
set -euo pipefail
cd "$(dirname "$0")/../.."
update_readme=()
seeds=()
for a in "$@"; do
  case "$a" in
    --update-readme) update_readme=(--update-readme) ;;
    *) [[ "$a" =~ ^[0-9]+$ ]] || { echo "ensemble.sh: seed '$a' is not a non-negative integer" >&2; exit 2; }
       seeds+=("$a") ;;
  esac
done
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
[ -x build/wearsim ] || { echo "ensemble.sh: build/wearsim not found; run bash scripts/build.sh" >&2; exit 1; }
source scripts/run_pool.sh
pool_init quick "${JOBS:-$(nproc)}" || exit 2
root=output/quick
mkdir -p "$root"
start=$(date +%s)

run_one() { # <kind> <seed>: one run, its case file and log beside its folder
  local out="$root/$1-$2"
  sed -e "s|^subsection DEM|subsection DEM\n  set Seed = $2|" \
      -e "s|set Directory = .*|set Directory = $out|" "cases/quick/$1.prm" > "$out.prm"
  build/wearsim run --overwrite "$out.prm" > "$out.log" 2>&1
}

for seed in "${seeds[@]}"; do
  for kind in plain convex; do
    pool_run "$kind-$seed" "$root/$kind-$seed.log" run_one "$kind" "$seed"
    echo "quick: $kind, seed $seed started"
  done
done
pool_wait || { printf 'quick: failed: %s\n' "${POOL_FAILED[@]}" >&2; exit 1; }

plain=() convex=()
for seed in "${seeds[@]}"; do plain+=("$root/plain-$seed"); convex+=("$root/convex-$seed"); done
# first=3: six revolutions need not reach steady state (two consecutive revolutions under
# DEM/Steady threshold), and compare refuses a run without revolutions after it; the four
# staged revolutions after the two settling ones are averaged instead
first=3
build/wearsim compare --from $first "${plain[@]}" -- "${convex[@]}" | tee "$root/compare.txt"
/usr/bin/python3 coupling/output/plot_run.py --compare --from $first "${plain[@]}" -- "${convex[@]}" \
  --output "$root"
/usr/bin/python3 coupling/output/plot_run.py "$root/plain-${seeds[0]}" "$root/convex-${seeds[0]}"
/usr/bin/python3 cases/quick/report.py "${update_readme[@]}" --from $first \
  --seconds $(( $(date +%s) - start )) "$root" "${seeds[@]}"
