#!/bin/bash
# scripts/run_pool.sh with stand-in runs: never more than JOBS at once, every run started and
# reported, failures listed with their log's error line, pool_stop ends what still runs.
set -uo pipefail
source "$(dirname "$0")/../../scripts/run_pool.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "run_pool_test: $*" >&2; exit 1; }

# A stand-in run: counts itself in and out of $tmp/running, records the most seen at once.
job() { # <name> <seconds> <exit status>
  (
    flock 9
    n=$(( $(cat "$tmp/running" 2>/dev/null || echo 0) + 1 ))
    echo $n > "$tmp/running"
    [ $n -gt "$(cat "$tmp/peak" 2>/dev/null || echo 0)" ] && echo $n > "$tmp/peak"
  ) 9> "$tmp/lock"
  sleep "$2"
  ( flock 9; echo $(( $(cat "$tmp/running") - 1 )) > "$tmp/running" ) 9> "$tmp/lock"
  [ "$3" -eq 0 ] || echo "error: run $1 failed on purpose" > "$tmp/$1.log"
  return "$3"
}

pool_init test 2 || fail "pool_init refused 2 jobs"
rc=0
{
  for k in 1 2 3 4 5; do
    status=0
    [ $k -eq 4 ] && status=3
    pool_run "run$k" "$tmp/run$k.log" job "run$k" 0.3 $status
  done
  pool_wait || rc=$?
} > "$tmp/out" 2>&1
[ $rc -ne 0 ] || fail "pool_wait returned 0 with a failed run"
[ "$(grep -c ' done (' "$tmp/out")" -eq 4 ] || fail "$(grep -c ' done (' "$tmp/out") runs reported done, 4 expected"
[ "$(cat "$tmp/peak")" -eq 2 ] || fail "peak of $(cat "$tmp/peak") runs at once, JOBS = 2"
[ ${#POOL_FAILED[@]} -eq 1 ] || fail "${#POOL_FAILED[@]} failures listed, 1 expected"
[[ "${POOL_FAILED[0]}" == "run4: error: run run4 failed on purpose ($tmp/run4.log)" ]] ||
  fail "failure listed as '${POOL_FAILED[0]}'"

# One at a time: the second run's own time leaves out the first's, the pool's time does not.
pool_init test 1 || fail "pool_init refused 1 job"
{
  pool_run first "$tmp/first.log" sleep 1
  pool_run second "$tmp/second.log" sleep 1
  pool_wait
} > "$tmp/out" 2>&1
line=$(grep 'second done' "$tmp/out") || fail "second run not reported: $(cat "$tmp/out")"
[[ "$line" =~ done\ \(([0-9]+)\ s,\ ([0-9]+)\ s\ since\ the\ pool\ started\) ]] ||
  fail "report '$line' does not give the run's own and the pool's seconds"
[ "${BASH_REMATCH[1]}" -lt "${BASH_REMATCH[2]}" ] ||
  fail "'$line': the run's own time includes the run before it"

pool_init test 1 || fail "pool_init refused 1 job"
pool_run slow "$tmp/slow.log" sleep 30
t0=$(date +%s)
pool_stop
[ $(( $(date +%s) - t0 )) -lt 10 ] || fail "pool_stop did not end a running job"
pool_init test 0 2> "$tmp/err" && fail "pool_init accepted JOBS = 0"
grep -q "JOBS='0' is not a positive integer" "$tmp/err" || fail "no message for JOBS = 0"
echo "run_pool_test: passed"
