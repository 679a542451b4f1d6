#!/bin/bash
# docs/results/reference_study_report.py refuses what it must not report from (issue 32): a
# study without its plain or convex run, runs (or a calibration) of different engine versions,
# runs of different Archard coefficients, and a calibration whose calibrated coefficient is not
# the one the runs used; and it accepts a complete set of one version (--check reads and checks
# the folders without writing). The run folders are stand-ins with the files the check reads.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
report="$root/docs/results/reference_study_report.py"
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
check() { # <runs> <calibration>: the report's check, its output in $tmp/out
  /usr/bin/python3 "$report" --check --runs "$1" --calibration "$2" > "$tmp/out" 2>&1
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
grep -q "c/convex' is missing" "$tmp/out" || fail "the refusal does not name the missing run: $(cat "$tmp/out")"

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
echo "reference_study_report_test: passed"
