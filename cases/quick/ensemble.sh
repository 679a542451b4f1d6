#!/bin/bash
# The quick case over several insertion seeds: how far one run's figures can be trusted.
# One run of the 30-degree sector lands in a slow or a fast bed (the bed's slip over the
# sample is intermittent), so its wear per revolution moves by a factor of about two with
# the seed, or with the last bit of a force sum. This runs plain and convex for each seed
# and prints the ensemble table (cases/quick/ensemble_report.py).
#
# usage: bash cases/quick/ensemble.sh [seed ...]     (default: 20111 1 2 3 4 5; on 2 cores
#        about 35 s per plain and 1 to 2 min per convex run, 13 min for the default twelve)
set -euo pipefail
cd "$(dirname "$0")/../.."
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(20111 1 2 3 4 5)
[ -x build/wearsim ] || { echo "ensemble.sh: build/wearsim not found; run bash scripts/build.sh" >&2; exit 1; }
root=output/quick-ensemble
mkdir -p "$root"
dirs=()
failed=()
for seed in "${seeds[@]}"; do
  [[ "$seed" =~ ^[0-9]+$ ]] || { echo "ensemble.sh: seed '$seed' is not a non-negative integer" >&2; exit 1; }
  for kind in plain convex; do
    out="$root/$kind-$seed"
    # the case file with its seed and output directory replaced; kept beside the output
    sed -e "s|^subsection DEM|subsection DEM\n  set Seed = $seed|" \
        -e "s|set Directory = .*|set Directory = $out|" cases/quick/$kind.prm > "$out.prm"
    echo "ensemble: $kind, seed $seed ($(date +%T))"
    if build/wearsim run --overwrite "$out.prm" > "$out.log" 2>&1; then
      dirs+=("$out")
    else
      # a failed run (e.g. a wear stage that would fold the surface) is reported and left out
      failed+=("$kind seed $seed: $(grep -m1 'error' "$out.log" || tail -n1 "$out.log") ($out.log)")
    fi
  done
done
{
  [ ${#dirs[@]} -eq 0 ] || /usr/bin/python3 cases/quick/ensemble_report.py "${dirs[@]}"
  for f in "${failed[@]}"; do echo "failed, left out: $f"; done
} | tee "$root/ensemble.txt"
[ ${#failed[@]} -eq 0 ]
