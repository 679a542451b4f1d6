#!/bin/bash
# The wear tester as a scene against the built-in tester of an older engine (TESTER: engine
# 883d1d5 or before, whose `wearsim run` ran a tester case on the built-in tester; the current
# engine runs a tester case as its scene, so both paths would be one): the small sector (cases/sector-30, plain
# and convex, 30-degree sector, s = 4, 2 dem-only and 4 staged revolutions at 20x) run both
# ways over the same insertion seeds, the scene written from the same case by
# `wearsim tester-scene`, one thread per run, as many runs at once as the machine
# has cores. compare_scene.py then sets each path's wear per revolution (revolutions 3 to 6)
# as mean +- 95 % interval across the seeds side by side and exits 1 when a scene mean falls
# outside the tester's interval. README.md beside this script says why not bit for bit.
#
# Then `wearsim compare --part sample` (which reads a built-in tester's run as its sample and
# a scene's evaluated sample alike) sets, per path, the convex sample's reduction against the
# plain one with its interval across the seeds (compare-tester.txt, compare-scene.txt), and
# per kind the scene against the tester (compare-plain.txt, compare-convex.txt).
#
# usage: bash cases/reference/scene/scene_vs_tester.sh [seed ...]
#        TESTER=<path> (required) the older engine's binary for the tester path
#        (default seeds 1 2 3: 16 min on 2 cores beside the test suite; JOBS=<n> sets the runs at once;
#         WEARSIM=<path> the binary, default build/wearsim; OUTPUT=<folder> the runs' folder,
#         default output/reference-scene; CASES=<folder> the plain.prm and convex.prm to run,
#         default cases/sector-30 (cases/quick: the default case); FROM=<k> the first
#         revolution averaged, default 3; SCHEDULE=<schedule> replaces the cases' Coupling/Schedule,
#         e.g. "6 reference" for the node-moving method on both paths)
set -euo pipefail
cd "$(dirname "$0")/../../.."
seeds=()
for a in "$@"; do
  [[ "$a" =~ ^[0-9]+$ ]] || { echo "scene_vs_tester.sh: seed '$a' is not a non-negative integer" >&2; exit 2; }
  seeds+=("$a")
done
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
wearsim=${WEARSIM:-build/wearsim}
[ -x "$wearsim" ] || { echo "scene_vs_tester.sh: $wearsim not found; run bash scripts/build.sh" >&2; exit 1; }
tester=${TESTER:-}
[ -n "$tester" ] && [ -x "$tester" ] ||
  { echo "scene_vs_tester.sh: TESTER='$tester' is not an executable: name the binary of an engine with the built-in tester (883d1d5 or older; git worktree add <dir> 883d1d5 and build it)" >&2; exit 2; }
source scripts/run_pool.sh
pool_init "scene vs tester" "${JOBS:-$(nproc)}" || exit 2
root=${OUTPUT:-output/reference-scene}
cases=${CASES:-cases/sector-30}
from=${FROM:-3}
schedule=${SCHEDULE:-}
[ -f "$cases/plain.prm" ] && [ -f "$cases/convex.prm" ] ||
  { echo "scene_vs_tester.sh: $cases has no plain.prm and convex.prm (CASES)" >&2; exit 2; }
mkdir -p "$root"
start=$(date +%s)

run_one() { # <path: tester|scene> <kind> <seed>
  local out="$root/$1-$2-$3"
  sed -e "s|^subsection DEM|subsection DEM\n  set Seed = $3|" \
      -e "s|set Directory = .*|set Directory = $out|" "$cases/$2.prm" > "$out.prm"
  [ -z "$schedule" ] || sed -i -e "s|set Schedule *= .*|set Schedule = $schedule|" "$out.prm"
  if [ "$1" = tester ]; then
    "$tester" run --overwrite "$out.prm" > "$out.log" 2>&1
  else
    "$wearsim" tester-scene "$out.prm" | sed -e "s|set Directory = .*|set Directory = $out|" \
      > "$out.scene.prm"
    "$wearsim" scene-run --overwrite "$out.scene.prm" > "$out.log" 2>&1
  fi
}

for seed in "${seeds[@]}"; do
  for kind in plain convex; do
    for path in tester scene; do
      pool_run "$path-$kind-$seed" "$root/$path-$kind-$seed.log" run_one "$path" "$kind" "$seed"
    done
  done
done
pool_wait || { printf 'scene vs tester: failed: %s\n' "${POOL_FAILED[@]}" >&2; exit 1; }
runs() { for seed in "${seeds[@]}"; do printf '%s ' "$root/$1-$2-$seed"; done; }
for path in tester scene; do
  "$wearsim" compare --part sample --from "$from" $(runs "$path" plain) -- $(runs "$path" convex) \
    > "$root/compare-$path.txt"
done
for kind in plain convex; do
  "$wearsim" compare --part sample --from "$from" $(runs tester "$kind") -- $(runs scene "$kind") \
    > "$root/compare-$kind.txt"
done
/usr/bin/python3 cases/reference/scene/compare_scene.py --from "$from" \
  --seconds $(( $(date +%s) - start )) --cases "$cases" "$root" "${seeds[@]}"
