# A pool of background runs, at most POOL_JOBS at once, for the case scripts (cases/quick/
# run.sh, cases/reference/scene/scene_vs_tester.sh, cases/reference-study/run.sh).
# Sourced, not run:
#
#   source scripts/run_pool.sh
#   pool_init <label> <jobs>      messages start with "<label>: "; jobs: a positive integer
#   pool_run <name> <log> <command> [argument ...]
#                                 starts the command in the background as soon as fewer than
#                                 <jobs> run; <log> is read for the failure message
#   pool_wait                     waits for every run; returns 1 when any failed, each failure
#                                 listed in POOL_FAILED as "<name>: <first error line> (<log>)"
#   pool_stop                     sends SIGTERM to every run still going and waits for them
#                                 (for a trap: runs that checkpoint on SIGTERM stop cleanly)
#
# A run is reported as it ends: "<label>: <name> done (<its own seconds> s, <seconds since
# pool_init> s since the pool started)", or on
# standard error "<label>: <name> failed with status <n> (<log>)".

pool_init() { # <label> <jobs>
  POOL_LABEL=$1
  POOL_JOBS=$2
  [[ "$POOL_JOBS" =~ ^[1-9][0-9]*$ ]] ||
    { echo "$POOL_LABEL: JOBS='$POOL_JOBS' is not a positive integer" >&2; return 2; }
  POOL_START=$(date +%s)
  POOL_FAILED=()
  declare -gA POOL_NAME=() POOL_LOG=() POOL_BEGAN=()
}

pool_reap_() { # <pid>: collects one finished run
  local pid=$1 rc=0
  local name=${POOL_NAME[$pid]} log=${POOL_LOG[$pid]} began=${POOL_BEGAN[$pid]}
  wait "$pid" || rc=$?
  if [ $rc -eq 0 ]; then
    local now
    now=$(date +%s)
    echo "$POOL_LABEL: $name done ($((now - began)) s, $((now - POOL_START)) s since the pool started)"
  else
    local why
    why=$(grep -m1 -i 'error' "$log" 2>/dev/null || tail -n1 "$log" 2>/dev/null || true)
    POOL_FAILED+=("$name: ${why:-exit status $rc} ($log)")
    echo "$POOL_LABEL: $name failed with status $rc ($log)" >&2
  fi
  unset "POOL_NAME[$pid]" "POOL_LOG[$pid]" "POOL_BEGAN[$pid]"
}

pool_drain_() { # <n>: collects runs as they end until at most n still run
  local done_pid
  while [ ${#POOL_NAME[@]} -gt "$1" ]; do
    wait -n -p done_pid "${!POOL_NAME[@]}" || true
    pool_reap_ "$done_pid"
  done
}

pool_run() { # <name> <log> <command> [argument ...]
  local name=$1 log=$2
  shift 2
  pool_drain_ $((POOL_JOBS - 1))
  "$@" &
  POOL_NAME[$!]=$name
  POOL_LOG[$!]=$log
  POOL_BEGAN[$!]=$(date +%s)
}

pool_wait() {
  pool_drain_ 0
  [ ${#POOL_FAILED[@]} -eq 0 ]
}

pool_stop() {
  local pid
  for pid in "${!POOL_NAME[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${!POOL_NAME[@]}"; do wait "$pid" 2>/dev/null || true; done
  POOL_NAME=()
  POOL_LOG=()
  POOL_BEGAN=()
}
