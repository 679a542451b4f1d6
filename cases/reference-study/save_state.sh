#!/usr/bin/env bash
# Keeps the study's runs in the repository, so that a run stopped at the end of a working
# session continues on the next machine (run.sh restores a kept run into an output folder that
# holds none). Only what the continuation and the report need is kept: the latest checkpoint
# (it holds the particles, the worn sample, every revolution and stage record), the resolved
# parameters (the engine version the report checks), the summaries, the field history and the
# stage surfaces. The volume files (about 11 MB per stage, for ParaView) and the snapshots are
# left out: the run writes them again from the next stage on.
#
# usage: bash cases/reference-study/save_state.sh [case ...]   (default: plain convex)
#        BUDGET_MB=<n>: refuse when the kept state would exceed n MB in all (default 120),
#        since every save adds its files to the repository's history.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=output/reference-study
kept_root=cases/reference-study/state
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(plain convex)
keep=(checkpoint.h5 parameters.prm summary.csv stages.csv history.h5 surface)
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
for c in "${cases[@]}"; do
  out="$root/$c"
  [ -f "$out/checkpoint.h5" ] ||
    { echo "save_state.sh: $out holds no checkpoint.h5 (nothing to keep for '$c')" >&2; exit 2; }
  mkdir -p "$staging/$c"
  for f in "${keep[@]}"; do
    [ -e "$out/$f" ] && cp -r "$out/$f" "$staging/$c/"
  done
  # What the kept run is: for the run.sh message and the status in the README.
  revs=$(($(wc -l < "$out/summary.csv") - 1))
  engine=$(sed -n 2p "$out/parameters.prm" | sed 's/^# Engine version: //')
  echo "$revs revolutions done, engine $engine, kept $(date -u +%FT%TZ)" > "$staging/$c/KEPT"
done
size_mb=$(du -sm "$staging" | cut -f1)
others=0
for d in "$kept_root"/*/; do
  [ -d "$d" ] || continue
  n=$(basename "$d")
  [[ " ${cases[*]} " == *" $n "* ]] || others=$((others + $(du -sm "$d" | cut -f1)))
done
budget=${BUDGET_MB:-120}
if [ $((size_mb + others)) -gt "$budget" ]; then
  echo "save_state.sh: the kept state would be $((size_mb + others)) MB, above BUDGET_MB=$budget" >&2
  exit 1
fi
for c in "${cases[@]}"; do
  rm -rf "$kept_root/$c.new"
  mkdir -p "$kept_root"
  mv "$staging/$c" "$kept_root/$c.new"
  rm -rf "$kept_root/$c"
  mv "$kept_root/$c.new" "$kept_root/$c"
  echo "save_state.sh: $c: $(cat "$kept_root/$c/KEPT") ($(du -sh "$kept_root/$c" | cut -f1))"
done
