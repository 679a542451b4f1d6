#!/bin/bash
# The default case: the reference study's set-up (150-degree tester, consolidator, the sample
# in its holder, calibrated alpha) at s = 7, plain and convex side by side, one thread each.
# Then `wearsim compare` prints every figure of the two sides as mean +- 95 % interval (batch
# means over each run's revolutions from the second), the comparison plot is drawn and
# cases/quick/report.py writes output/quick/report.md: the reduction, its distance from the
# full study at s = 7 and the study's answer at s = 3 (from the committed summaries of
# cases/reference-study/results); with --update-readme also the README's figures and picture.
#
# usage: bash cases/quick/run.sh [--update-readme]
#        (about 4 min on 2 cores; JOBS=<n> sets the runs at once, default the core count)
set -euo pipefail
cd "$(dirname "$0")/../.."
update_readme=()
for a in "$@"; do
  case "$a" in
    --update-readme) update_readme=(--update-readme) ;;
    *) echo "run.sh: unknown argument '$a' (only --update-readme)" >&2; exit 2 ;;
  esac
done
[ -x build/wearsim ] || { echo "run.sh: build/wearsim not found; run bash scripts/build.sh" >&2; exit 1; }
source scripts/run_pool.sh
pool_init quick "${JOBS:-$(nproc)}" || exit 2
root=output/quick
mkdir -p "$root"
start=$(date +%s)
run_one() { # <kind>: one run, its log beside its folder
  build/wearsim run --overwrite "cases/quick/$1.prm" > "$root/$1.log" 2>&1
}
# convex first: it is the longer of the two (more contacts, a remesh now and then)
for kind in convex plain; do
  pool_run "$kind" "$root/$kind.log" run_one "$kind"
  echo "quick: $kind started (log: $root/$kind.log)"
done
pool_wait || { printf 'quick: failed: %s\n' "${POOL_FAILED[@]}" >&2; exit 1; }

# first=2: the first revolution carries the bed's spin-up from rest; six revolutions need not
# meet the steady judgement (two consecutive revolutions under DEM/Steady threshold), and
# compare refuses a run without revolutions after it, so revolutions 2 to 6 are averaged
first=2
build/wearsim compare --from $first "$root/plain" -- "$root/convex" | tee "$root/compare.txt"
/usr/bin/python3 coupling/output/plot_run.py --compare --from $first "$root/plain" -- "$root/convex" \
  --output "$root" > /dev/null
/usr/bin/python3 coupling/output/plot_run.py "$root/plain" "$root/convex" > /dev/null
/usr/bin/python3 cases/quick/report.py "${update_readme[@]}" --from $first \
  --seconds $(( $(date +%s) - start )) "$root"
