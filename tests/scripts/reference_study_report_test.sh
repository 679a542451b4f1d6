#!/bin/bash
# docs/results/reference_study_report.py refuses what it must not report from (issue 32): a
# study without its plain or convex run, runs (or a calibration) of different engine versions,
# runs of different Archard coefficients, and a calibration whose calibrated coefficient is not
# the one the runs used; and it accepts a complete set of one version (--check reads and checks
# the folders without writing). Its node-moving section tells how each `reference` run ended
# (distorted, through its schedule, or stopped, from its log) and its wear against the staged
# run's over the same revolutions. The run folders are stand-ins with the files it reads,
# summarised by docs/results/run_summary.py as run.sh does (the report reads summaries only).
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
report="$root/docs/results/reference_study_report.py"
summary="$root/docs/results/run_summary.py"
source "$root/tests/scripts/stand_in_summaries.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "reference_study_report_test: $*" >&2; exit 1; }

run_folder() { # <folder> <engine>: a stand-in `wearsim run` folder, 1 dem-only + 1 staged
  mkdir -p "$1"
  printf '# Fully resolved parameters of cases/reference-study/%s.prm\n# Engine version: %s\n' \
    "$(basename "$1")" "$2" > "$1/parameters.prm"
  printf 'revolution,wear_volume_m3,steady_revolution\n1,7e-08,0\n2,7.1e-08,1\n' > "$1/summary.csv"
  printf 'stage,scheme_name,first_revolution\n1,dem-only,1\n2,staged,2\n' > "$1/stages.csv"
  /usr/bin/python3 -c "import h5py, sys; h5py.File(sys.argv[1], 'w').close()" "$1/history.h5" ||
    fail "cannot write a stand-in history.h5 (python3-h5py)"
}
check() { # <runs> <calibration>: the report's check on their summaries, its output in $tmp/out
  summarise_stand_ins "$1"
  rm -rf "$2.summary"
  /usr/bin/python3 "$summary" "$2" "$2.summary" > /dev/null || fail "run_summary.py refused the stand-in $2"
  /usr/bin/python3 "$report" --check --runs "$1.summaries" --calibration "$2.summary" > "$tmp/out" 2>&1
}

run_folder "$tmp/a/plain" e1
run_folder "$tmp/a/convex" e1
run_folder "$tmp/a/plain-seed2" e1
run_folder "$tmp/cal" e1
check "$tmp/a" "$tmp/cal" || fail "refused a complete set of one engine: $(cat "$tmp/out")"
grep -q "3 runs" "$tmp/out" && grep -q "engine e1" "$tmp/out" && grep -q "calibration present" "$tmp/out" ||
  fail "the check did not name the runs, the engine and the calibration: $(cat "$tmp/out")"
grep -q "convex-seed2" "$tmp/out" || fail "the check did not list the runs not run: $(cat "$tmp/out")"

# The calibration of another engine.
run_folder "$tmp/cal2" e2
check "$tmp/a" "$tmp/cal2" && fail "accepted a calibration of another engine"
grep -q "different engine versions" "$tmp/out" && grep -q "calibration: e2" "$tmp/out" ||
  fail "the refusal does not name the calibration's engine: $(cat "$tmp/out")"

# A run of another engine.
run_folder "$tmp/b/plain" e1
run_folder "$tmp/b/convex" e1
run_folder "$tmp/b/convex-s4" e3
check "$tmp/b" "$tmp/cal" && fail "accepted a run of another engine"
grep -q "convex-s4: e3" "$tmp/out" || fail "the refusal does not name the odd run: $(cat "$tmp/out")"

# The study pair incomplete.
run_folder "$tmp/c/plain" e1
check "$tmp/c" "$tmp/cal" && fail "accepted a study without its convex run"
grep -q "c.summaries/convex' is missing" "$tmp/out" || fail "the refusal does not name the missing run: $(cat "$tmp/out")"

# A run folder without its engine version (older than the study).
run_folder "$tmp/d/plain" e1
run_folder "$tmp/d/convex" e1
sed -i 2d "$tmp/d/convex/parameters.prm"
check "$tmp/d" "$tmp/cal" && fail "accepted a run that names no engine version"
grep -q "names no engine version" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"
# Runs of different Archard coefficients (every case includes one calibration.prm).
alpha() { printf '  set Archard coefficient = %s\n' "$2" >> "$1/parameters.prm"; }
run_folder "$tmp/e/plain" e1
run_folder "$tmp/e/convex" e1
alpha "$tmp/e/plain" 7.25779635e-09
alpha "$tmp/e/convex" 5e-09
check "$tmp/e" "$tmp/cal" && fail "accepted runs of different Archard coefficients"
grep -q "different Archard coefficients" "$tmp/out" && grep -q "convex: 5e-09" "$tmp/out" ||
  fail "the refusal does not name the coefficients: $(cat "$tmp/out")"

# A calibration that calibrated another coefficient than the runs use; the kept calibration
# (no history.h5) that calibrated theirs.
sed -i '$d' "$tmp/e/convex/parameters.prm"
alpha "$tmp/e/convex" 7.25779635e-09
printf 'subsection Wear law\n  set Archard coefficient = 7.3e-09\nend\n' > "$tmp/cal/calibration.prm"
check "$tmp/e" "$tmp/cal" && fail "accepted a calibration whose coefficient the runs do not use"
grep -q "calibrated alpha = 7.3e-09" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"
printf 'subsection Wear law\n  set Archard coefficient = 7.25779635e-09\nend\n' > "$tmp/cal/calibration.prm"
rm "$tmp/cal/history.h5" "$tmp/cal/stages.csv"
check "$tmp/e" "$tmp/cal" || fail "refused the kept calibration of the runs' coefficient: $(cat "$tmp/out")"
grep -q "calibration present" "$tmp/out" || fail "the kept calibration was not read: $(cat "$tmp/out")"

# The node-moving runs against the staged ones (stand-ins: plain and convex staged from
# revolution 2 at 71 and 50 mm^3): a distorted run, one that ran its whole schedule and one
# that run.sh stopped (it keeps no checkpoint), told from its log.
reference_folder() { # <folder> <planned revolutions> <wear per revolution [m^3]> <distortion per stage ...>
  local d=$1 n=$2 v=$3 k=0
  shift 3
  run_folder "$d" e1
  printf '  set Schedule = %s reference\n' "$n" >> "$d/parameters.prm"
  printf 'revolution,wear_volume_m3,steady_revolution\n' > "$d/summary.csv"
  printf 'stage,scheme_name,first_revolution,distortion\n' > "$d/stages.csv"
  for dist in "$@"; do
    k=$((k + 1))
    printf '%d,%s,0\n' "$k" "$v" >> "$d/summary.csv"
    printf '%d,reference,%d,"%s"\n' "$k" "$k" "$dist" >> "$d/stages.csv"
  done
}
section() { # <runs>: the node-moving section of the report on these folders, in $tmp/out
  summarise_stand_ins "$1"
  /usr/bin/python3 - "$root/docs/results" "$1.summaries" > "$tmp/out" 2>&1 <<'PY'
import os, sys
sys.path.insert(0, sys.argv[1])
import reference_study_report as R
runs = {n: R.Run(os.path.join(sys.argv[2], n)) for n in sorted(os.listdir(sys.argv[2]))
        if os.path.isdir(os.path.join(sys.argv[2], n))}
print("\n".join(R.node_moving_section(runs)))
PY
}
run_folder "$tmp/f/plain" e1
run_folder "$tmp/f/convex" e1
sed -i 's/^2,7.1e-08/2,5e-08/' "$tmp/f/convex/summary.csv"
reference_folder "$tmp/f/plain-reference" 3 2e-7 "" "inverted face at face 5 (C11), t = 3.1 s"
reference_folder "$tmp/f/convex-reference" 3 1e-7 "" ""
printf '=== t0 wearsim run --overwrite c.prm\nstopped by SIGTERM in stage 3 of 3 (revolution 3, t = 4 s); nothing was saved\n' \
  > "$tmp/f/convex-reference.log"
section "$tmp/f" || fail "no node-moving section: $(cat "$tmp/out")"
grep -qF "| plain | 2 | distorted in revolution 2: inverted face at face 5 (C11), t = 3.1 s | 200.00 | 70.50 | 200.00 (1 revolution) | 71.00 |" "$tmp/out" ||
  fail "the distorted run is not told, or its wear from revolution 2 is not 200 against 71: $(cat "$tmp/out")"
grep -qF "| convex | 2 | stopped by SIGTERM in stage 3 of 3 | 100.00 | 60.00 | 100.00 (1 revolution) | 50.00 |" "$tmp/out" ||
  fail "the stopped run is not told from its log: $(cat "$tmp/out")"
reference_folder "$tmp/f/convex-reference" 3 1e-7 "" "" ""
section "$tmp/f" || fail "no node-moving section: $(cat "$tmp/out")"
grep -qF "| convex | 3 | all 3 revolutions, undistorted | 100.00 | n/a | 200.00 (2 revolutions) | n/a |" "$tmp/out" ||
  fail "a run through its schedule is not told as such: $(cat "$tmp/out")"
reference_folder "$tmp/f/plain-reference" 3 2e-7 "inverted face at face 7 (C12), t = 1.5 s"
section "$tmp/f" || fail "no node-moving section: $(cat "$tmp/out")"
grep -qF "| plain | 1 | distorted in revolution 1: inverted face at face 7 (C12), t = 1.5 s | 200.00 | 70.00 | none: it ended before revolution 2 | |" "$tmp/out" ||
  fail "a run that distorted before the staged revolutions is not told as such: $(cat "$tmp/out")"

# The size trend while s = 2 runs: a run short of 56 h after steady state says how far it got
# (plain-s2 1 of 5 revolutions, convex-s2 started without a revolution) and its wear so far
# against s = 3's same revolutions; the stand-in s = 3 pair reaches 56 h (2 revolutions from 2).
trend() { # <runs>: the size-trend section on these folders (missing: R.load_runs'), in $tmp/out
  summarise_stand_ins "$1"
  /usr/bin/python3 - "$root/docs/results" "$1.summaries" > "$tmp/out" 2>&1 <<'PY2'
import sys
sys.path.insert(0, sys.argv[1])
import reference_study_report as R
runs, missing, _ = R.load_runs(sys.argv[2], sys.argv[2] + "/none")
print("\n".join(R.size_trend_section(runs, missing)))
PY2
}
run_folder "$tmp/g/plain" e1
run_folder "$tmp/g/convex" e1
printf '3,7.2e-08,1\n' >> "$tmp/g/plain/summary.csv"
printf '3,5.2e-08,1\n' >> "$tmp/g/convex/summary.csv"
for k in plain convex; do
  printf 'stage,scheme_name,first_revolution,amplification\n1,dem-only,1,1\n2,staged,2,1\n3,staged,3,1\n' \
    > "$tmp/g/$k/stages.csv"
done
run_folder "$tmp/g/plain-s2" e1
printf '  set Schedule = 3 dem-only, 2 staged\n' >> "$tmp/g/plain-s2/parameters.prm"
printf 'revolution,wear_volume_m3,steady_revolution\n1,6.5e-08,0\n' > "$tmp/g/plain-s2/summary.csv"
printf 'stage,scheme_name,first_revolution\n1,dem-only,1\n' > "$tmp/g/plain-s2/stages.csv"
mkdir -p "$tmp/g/convex-s2"  # started: its parameters and the header of its summary.csv
sed 's/plain-s2/convex-s2/' "$tmp/g/plain-s2/parameters.prm" > "$tmp/g/convex-s2/parameters.prm"
printf 'revolution,wear_volume_m3,steady_revolution\n' > "$tmp/g/convex-s2/summary.csv"
trend "$tmp/g" || fail "no size-trend section: $(cat "$tmp/out")"
grep -qF "| 3 | 143.00 | 123.00 | 0.860 | plain: 1, 1; convex: 1, 1 |" "$tmp/out" ||
  fail "the s = 3 pair at 56 h is not 143 and 123 mm^3: $(cat "$tmp/out")"
grep -qF "| 2 | not reached: 1 of 5 revolutions done | not reached: started, no revolution done |  |  |" "$tmp/out" ||
  fail "the s = 2 row does not say how far its runs got: $(cat "$tmp/out")"
grep -qF "| 4 | not run | not run |  |  |" "$tmp/out" ||
  fail "the s = 4 row does not say it was not run: $(cat "$tmp/out")"
grep -qF -- "- plain-s2 (s = 3 in brackets): revolution 1: 65.00 (70.00) mm^3." "$tmp/out" ||
  fail "the s = 2 wear so far is not set against s = 3's: $(cat "$tmp/out")"
echo "reference_study_report_test: passed"
