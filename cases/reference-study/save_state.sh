#!/usr/bin/env bash
# Keeps the study's runs in the repository, so that a run stopped at the end of a working
# session continues on the next machine (run.sh restores a kept run into an output folder that
# holds none). Only what the continuation and the report need is kept, as one xz archive per
# run, state/<case>.tar.xz, with a line saying what it holds in state/<case>.txt:
#   checkpoint.h5 (particles, worn sample, every revolution and stage record; a run of the
#   reference scheme has none and is kept as far as it went, never over a kept one that went
#   further, and is not continued but started afresh by run.sh), parameters.prm
#   (the engine version the report checks), summary.csv, stages.csv, history.h5, and the first
#   and the last stage surface (surface/stage_*.h5: the unworn sample and the latest worn one,
#   the two the report maps and profiles);
#   the other stage surfaces and every volume/stage_*.h5 as stubs holding only their index
#   entry (the root attribute "xdmf"): a resume re-reads that entry of every stage and nothing
#   else, and the fields themselves (2.5 MB per surface and 11 MB per volume stage) are for
#   ParaView. The kept run's xdmf indexes therefore list stages whose fields are gone; the
#   stages run after the restore have theirs.
# Left out: the initial sample mesh (mesh/), the .vtu copies, the xdmf indexes (rewritten on
# resume) and the snapshots.
#
# usage: bash cases/reference-study/save_state.sh [case ...]   (default: plain convex)
#        case: as for run.sh (case_paths.sh): a name here, or the path of another case file;
#              `calibration` keeps output/calibration-plain's parameters.prm, summary.csv and
#              calibration.prm in state/calibration-plain (the report's calibration; its
#              history.h5 of particles and face fields is left out)
#        BUDGET_MB=<n>: refuse when the kept archives would exceed n MB in all (default 200:
#        the study's runs, 110 MB, the wear-out and stress runs, about 10 MB each, and
#        the two s = 2 runs, about 40 MB each),
#        since every save adds its archives to the repository's history.
set -euo pipefail
cd "$(dirname "$0")/../.."
source cases/reference-study/case_paths.sh
kept_root=cases/reference-study/state
mkdir -p "$kept_root"
keep_calibration() { # the calibration run (a `wearsim dem` run): what the report reads of it
  local from=output/calibration-plain to=$kept_root/calibration-plain f
  for f in parameters.prm summary.csv calibration.prm; do
    [ -f "$from/$f" ] || { echo "save_state.sh: $from/$f does not exist (run and calibrate first)" >&2; exit 2; }
  done
  mkdir -p "$to"
  for f in parameters.prm summary.csv calibration.prm; do cp "$from/$f" "$to/$f.tmp" && mv "$to/$f.tmp" "$to/$f"; done
  echo "save_state.sh: calibration: $(($(wc -l < "$to/summary.csv") - 1)) revolutions, kept in $to"
}
args=()
for a in "$@"; do
  if [ "$a" = calibration ]; then keep_calibration; else args+=("$a"); fi
done
[ $# -gt 0 ] || args=(plain convex)
[ ${#args[@]} -gt 0 ] || exit 0
cases=()
for a in "${args[@]}"; do cases+=("$(kept_name "$a")"); done
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
for i in "${!args[@]}"; do
  c=${cases[$i]} out=$(out_dir "${args[$i]}")
  if [ ! -f "$out/checkpoint.h5" ]; then
    # the reference scheme keeps no checkpoint: its run is kept as far as it went, the
    # records and surfaces the report reads, but never in place of a kept one that went further
    grep -q '^[[:space:]]*set Schedule[[:space:]]*=[^#]*reference' "$out/parameters.prm" 2>/dev/null &&
      [ -f "$out/summary.csv" ] ||
      { echo "save_state.sh: $out holds no checkpoint.h5 (nothing to keep for '$c')" >&2; exit 2; }
    revs=$(($(wc -l < "$out/summary.csv") - 1))
    kept_revs=$(sed -n 's/^[^:]*: \([0-9]*\) revolutions done.*/\1/p' "$kept_root/$c.txt" 2>/dev/null || true)
    if [ -n "$kept_revs" ] && [ "$revs" -lt "$kept_revs" ]; then
      echo "save_state.sh: $out has $revs revolutions, the kept run of '$c' $kept_revs: kept as it is" >&2
      exit 1
    fi
  fi
  s="$staging/$c"
  mkdir -p "$s/surface" "$s/volume"
  for f in checkpoint.h5 parameters.prm summary.csv stages.csv history.h5; do
    [ -f "$out/$f" ] && cp "$out/$f" "$s/"
  done
  # the log run.sh writes beside the folder: how the run ended, for the reports
  if [ -f "$out.log" ]; then cp "$out.log" "$s/run.log"; elif [ -f "$out/run.log" ]; then cp "$out/run.log" "$s/"; fi
  surfaces=("$out"/surface/stage_*.h5)
  [ -f "${surfaces[0]}" ] || surfaces=()
  for v in "${surfaces[@]}" "$out"/volume/stage_*.h5; do
    [ -f "$v" ] || continue
    kind=$(basename "$(dirname "$v")")
    if [ "$kind" = surface ] && { [ "$v" = "${surfaces[0]}" ] || [ "$v" = "${surfaces[-1]}" ]; }; then
      cp "$v" "$s/surface/"
      continue
    fi
    /usr/bin/python3 - "$v" "$s/$kind/$(basename "$v")" <<'EOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as src, h5py.File(sys.argv[2], "w") as dst:
    dst.attrs["xdmf"] = src.attrs["xdmf"]
EOF
  done
  revs=$(($(wc -l < "$out/summary.csv") - 1))
  engine=$(sed -n 2p "$out/parameters.prm" | sed 's/^# Engine version: //')
  echo "$c: $revs revolutions done, engine $engine, kept $(date -u +%FT%TZ)" > "$staging/$c.txt"
  tar -C "$s" -cf - . | xz -6 -T1 > "$staging/$c.tar.xz"
done
new_kb=0
for c in "${cases[@]}"; do new_kb=$((new_kb + $(du -k "$staging/$c.tar.xz" | cut -f1))); done
others_kb=0
for a in "$kept_root"/*.tar.xz; do
  [ -f "$a" ] || continue
  n=$(basename "$a" .tar.xz)
  [[ " ${cases[*]} " == *" $n "* ]] || others_kb=$((others_kb + $(du -k "$a" | cut -f1)))
done
budget=${BUDGET_MB:-200}
if [ $(((new_kb + others_kb) / 1024)) -gt "$budget" ]; then
  echo "save_state.sh: the kept archives would be $(((new_kb + others_kb) / 1024)) MB, above BUDGET_MB=$budget" >&2
  exit 1
fi
for c in "${cases[@]}"; do
  mv "$staging/$c.tar.xz" "$kept_root/$c.tar.xz.tmp" && mv "$kept_root/$c.tar.xz.tmp" "$kept_root/$c.tar.xz"
  mv "$staging/$c.txt" "$kept_root/$c.txt"
  echo "save_state.sh: $(cat "$kept_root/$c.txt") ($(du -h "$kept_root/$c.tar.xz" | cut -f1))"
done
