#!/usr/bin/env bash
# Runs (or continues) cases of the reference study, as many at once as the machine has cores,
# one DEM thread each (DEM/Threads = 1 in the case files). A case whose folder holds a
# checkpoint continues with --resume (a finished run returns at once), otherwise it starts.
# Stop everything with Ctrl-C or `kill -TERM <pid of this script>`: each run writes a
# checkpoint and exits; the next call continues it.
#
# usage: bash cases/reference-study/run.sh [case ...]
#        case: the name of a case file here without .prm (default: plain convex)
#        WEARSIM=<binary> (default build/wearsim; the study's engine is named in its report),
#        JOBS=<n> runs at once (default: the number of cores)
set -uo pipefail
cd "$(dirname "$0")/../.."
wearsim=${WEARSIM:-build/wearsim}
jobs=${JOBS:-$(nproc)}
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(plain convex)
for c in "${cases[@]}"; do
  [ -f "cases/reference-study/$c.prm" ] ||
    { echo "run.sh: no case file cases/reference-study/$c.prm" >&2; exit 2; }
done
[ -x "$wearsim" ] || { echo "run.sh: no wearsim binary at '$wearsim' (WEARSIM)" >&2; exit 2; }
root=output/reference-study
mkdir -p "$root"
echo "reference study: $("$wearsim" --version), ${#cases[@]} case(s), $jobs at once"

run_one() { # <case>: start or continue one case, its log beside its folder
  local prm="cases/reference-study/$1.prm" out="$root/$1" mode=--overwrite
  [ -f "$out/checkpoint.h5" ] && mode=--resume
  echo "=== $(date -u +%FT%TZ) $wearsim run $mode $prm" >> "$out.log"
  exec "$wearsim" run "$mode" "$prm" >> "$out.log" 2>&1
}

declare -A pid_of=()
status=0
stop_all() {
  for p in "${!pid_of[@]}"; do kill -TERM "$p" 2>/dev/null; done
  wait
  echo "reference study: stopped; continue with the same command"
  exit 130
}
trap stop_all INT TERM
reap() {
  local pid=$1 name=${pid_of[$1]} rc=0
  wait "$pid" || rc=$?
  if [ $rc -eq 0 ]; then
    echo "reference study: $name done $(date -u +%TZ)"
  else
    echo "reference study: $name stopped with status $rc ($root/$name.log)"
    status=1
  fi
  unset "pid_of[$pid]"
}
for c in "${cases[@]}"; do
  while [ ${#pid_of[@]} -ge "$jobs" ]; do
    wait -n -p done_pid "${!pid_of[@]}" || true
    reap "$done_pid"
  done
  echo "reference study: $c started $(date -u +%TZ)"
  run_one "$c" &
  pid_of[$!]="$c"
done
while [ ${#pid_of[@]} -gt 0 ]; do
  wait -n -p done_pid "${!pid_of[@]}" || true
  reap "$done_pid"
done
exit $status
