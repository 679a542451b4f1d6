#!/usr/bin/env bash
# Runs (or continues) cases of the reference study, as many at once as the machine has cores,
# one DEM thread each (DEM/Threads = 1 in plain, convex and the wear-out and stress cases; the
# seeds and the other particle sizes use 2 threads and run with JOBS=1). A case whose folder
# holds a checkpoint continues with --resume (a finished run returns at once), otherwise it
# starts.
# Stop everything with Ctrl-C or `kill -TERM <pid of this script>`: each run writes a
# checkpoint and exits; the next call continues it.
#
# usage: bash cases/reference-study/run.sh [case ...]
#        case: the name of a case file here without .prm (default: plain convex), or the
#              path of another case file run by the study's engine (cases/wear-out/convex.prm);
#              its output folder is the `set Directory` the file itself writes
#        WEARSIM=<binary> (default: the study's engine, engine.sh, built on first use: the
#        commit in the ENGINE file beside the first case's file when there is one, as
#        cases/wear-out/ENGINE, else cases/reference-study/ENGINE; the cases of one call
#        share it),
#        JOBS=<n> runs at once (default: the number of cores)
# A case whose output folder holds no run but whose unfinished run is kept in
# cases/<case>/running/<run> (keep_running.sh, carried between machines in the repository)
# continues from the kept checkpoint; a node-moving (`reference`) run keeps none and starts
# afresh.
# When its runs have ended (finished, stopped or failed), each case's run is summarised into
# cases/<case>/results/<run> (docs/results/run_summary.py), what the reports read; a run
# without a checkpoint replaces the summary of the same case only when it went further.
# A case whose run has a summary but neither a run in its output folder nor a kept checkpoint
# has ended (finished, distorted, or stopped by an error or without a checkpoint) and is not
# run again. AFRESH=1 starts every case given from the beginning, whatever its output folder or
# kept checkpoint holds (its summary is replaced when it stops, unless it keeps no checkpoint
# and gets less far); without it a case continues from its checkpoint.
set -uo pipefail
cd "$(dirname "$0")/../.."
wearsim=${WEARSIM:-}
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(plain convex)
source cases/reference-study/case_paths.sh
engine_of() { # <case>: the ENGINE file its study runs with
  local own
  own="$(dirname "$(case_file "$1")")/ENGINE"
  [ -f "$own" ] && echo "$own" || echo cases/reference-study/ENGINE
}
engine_file=$(engine_of "${cases[0]}")
for c in "${cases[@]}"; do
  [ "$(engine_of "$c")" = "$engine_file" ] ||
    { echo "run.sh: $c runs with $(engine_of "$c"), ${cases[0]} with $engine_file: run them apart" >&2; exit 2; }
done
if [ -z "$wearsim" ]; then
  wearsim=$(bash cases/reference-study/engine.sh "$engine_file") || { echo "run.sh: no study engine" >&2; exit 2; }
fi
source scripts/run_pool.sh
pool_init "reference study" "${JOBS:-$(nproc)}" || exit 2
for c in "${cases[@]}"; do
  [ -f "$(case_file "$c")" ] || { echo "run.sh: no case file $(case_file "$c")" >&2; exit 2; }
  [ -n "$(out_dir "$c")" ] || { echo "run.sh: $c sets no Output/Directory of its own" >&2; exit 2; }
done
[ -x "$wearsim" ] || { echo "run.sh: no wearsim binary at '$wearsim' (WEARSIM)" >&2; exit 2; }
echo "reference study: $("$wearsim" --version), ${#cases[@]} case(s), $POOL_JOBS at once"

run_one() { # <case>: start or continue one case, its log beside its folder
  local prm out mode=--overwrite
  prm=$(case_file "$1") out=$(out_dir "$1")
  mkdir -p "$(dirname "$out")"
  [ -f "$out/checkpoint.h5" ] && [ -z "${AFRESH:-}" ] && mode=--resume
  echo "=== $(date -u +%FT%TZ) $wearsim run $mode $prm" >> "$out.log"
  exec "$wearsim" run "$mode" "$prm" >> "$out.log" 2>&1
}

summarise_all() { # every case's run summarised (run_summary.py), whatever became of it
  local c
  for c in "${cases[@]}"; do
    summarise "$c" | sed 's/^/reference study: /' || echo "reference study: $c not summarised" >&2
  done
}

stop_all() {
  pool_stop
  summarise_all
  echo "reference study: stopped; continue with the same command (keep_running.sh keeps the runs)"
  exit 130
}
trap stop_all INT TERM
ended() { # <case>: whether its run has ended on some machine (a summary, nothing to continue)
  [ -z "${AFRESH:-}" ] && [ -f "$(summary_dir "$1")/run.txt" ] && ! holds_run "$(out_dir "$1")" &&
    [ ! -f "$(running_dir "$1")/checkpoint.h5.xz" ]
}
for c in "${cases[@]}"; do
  if ended "$c"; then
    echo "reference study: $c has ended (its summary: $(summary_dir "$c")); AFRESH=1 runs it again"
    continue
  fi
  restored=
  [ -n "${AFRESH:-}" ] || restored=$(restore_running "$c") || exit 2
  [ -z "$restored" ] || echo "reference study: continues from the kept checkpoint: $restored"
  pool_run "$c" "$(out_dir "$c").log" run_one "$c"
  echo "reference study: $c started $(date -u +%TZ)"
done
pool_wait
failed=$?
summarise_all
[ $failed -eq 0 ] || { printf 'reference study: stopped with an error: %s\n' "${POOL_FAILED[@]}"; exit 1; }
