#!/bin/bash
# docs/results/holder_cases_report.py (issue 32, item 6) reports the wear-out and stress runs
# it finds and lists the others as not run; it refuses a root with none of them, a run of
# another engine version than the study's and a run that names none. Its arithmetic is checked
# on stand-in stages with known figures: two staged stages at 10x stand for 560 h, and a law
# that scales the convex sample's wear by 1.2 and the plain one's by 1 turns a DEM ratio of
# 0.5 into 0.6 (10 percentage points narrower); a run short of its schedule is told as stopped by
# an error or by SIGTERM from the last part of its log, and an element's height is its highest
# point above the unworn base top. The run folders are stand-ins with the files
# the report reads, summarised by docs/results/run_summary.py as run.sh does (the report reads
# summaries only).
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
report="$root/docs/results/holder_cases_report.py"
summary="$root/docs/results/run_summary.py"
source "$root/tests/scripts/stand_in_summaries.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "holder_cases_report_test: $*" >&2; exit 1; }

run_folder() { # <folder> <engine> <dem wear per stage [m^3]> <stress factor>: 1 dem-only + 2 staged at 10x
  mkdir -p "$1"
  printf '# Fully resolved parameters of cases/stress/%s.prm\n# Engine version: %s\n' "$(basename "$1")" "$2" > "$1/parameters.prm"
  printf '  set Schedule = 1 dem-only, 2 staged\n  set Amplification = 10\n  set Enabled = true\n  set Sensitivity = 1\n  set Reference stress = 1e5\n  set Exponent = 1\n' >> "$1/parameters.prm"
  printf 'revolution,wear_volume_m3,steady_revolution\n1,%s,0\n2,%s,1\n3,%s,1\n' "$3" "$3" "$3" > "$1/summary.csv"
  /usr/bin/python3 - "$1/stages.csv" "$3" "$4" <<'PY' || fail "cannot write stand-in stages.csv"
import sys
path, dem, factor = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
cols = ["stage", "scheme_name", "first_revolution", "last_revolution", "amplification", "dem_wear_volume_m3",
        "applied_volume_m3", "cumulative_applied_m3", "mean_stress_factor", "max_von_mises_ball_Pa",
        "safety_factor", "max_depth_m", "remeshes", "min_scaled_jacobian", "worn_through_faces"]
rows = [[1, "dem-only", 1, 1, 1, dem, 0, 0, 1, 0, 0, 0, 0, 0, 0]]
cum = 0.0
for k in (2, 3):
    cum += 10 * factor * dem
    rows.append([k, "staged", k, k, 10, dem, 10 * factor * dem, cum, factor, 1.5e5, 130, 1e-4, 0, 0.2, 0])
with open(path, "w") as f:
    f.write(",".join(cols) + "\n")
    for r in rows:
        f.write(",".join(str(x) for x in r) + "\n")
PY
  /usr/bin/python3 -c "import h5py, sys; h5py.File(sys.argv[1], 'w').close()" "$1/history.h5" ||
    fail "cannot write a stand-in history.h5 (python3-h5py)"
}
check() { # <root> [--out dir]: the report on the summaries of a root's runs, its output in $tmp/out
  local r=$1
  shift
  summarise_stand_ins "$r"
  /usr/bin/python3 "$report" --root "$r.summaries" --engine e1 "$@" > "$tmp/out" 2>&1
}

run_folder "$tmp/a/stress-plain" e1 1e-7 1.0
run_folder "$tmp/a/stress-convex" e1 5e-8 1.2
check "$tmp/a" --out "$tmp/a/report" || fail "refused two runs of one engine: $(cat "$tmp/out")"
md="$tmp/a/report/holder-cases.md"
[ -f "$md" ] && [ -f "$tmp/a/report/holder_cases.png" ] || fail "wrote no report or no plot"
grep -q "wear-out-convex" "$md" && grep -q "Not run" "$md" || fail "the missing wear-out run is not listed as not run"
grep -q "| 2 of 2 | 560 |" "$md" || fail "two staged stages at 10x do not stand for 560 h: $(grep stress-plain "$md")"
grep -q "Archard) wear \*\*0.500\*\*" "$md" || fail "the DEM convex/plain is not 0.500: $(grep '^Over' "$md")"
grep -q "amplification \*\*0.600\*\*" "$md" || fail "the applied convex/plain is not 0.600: $(grep '^Over' "$md")"
grep -q "narrows the convex sample's advantage by 10.0 percentage points" "$md" ||
  fail "the law's effect is not 10.0 points: $(grep '^Over' "$md")"
grep -q "1 + 1 (sigma_vM / 1e5 Pa)" "$md" || fail "the law is not named: $(grep '^The' "$md")"

# How a run short of its schedule ended, from the last call's part of the log beside its folder.
run_folder "$tmp/e/wear-out-convex" e1 5e-8 1.0
sed -i 's/2 staged/5 staged/' "$tmp/e/wear-out-convex/parameters.prm"
wlog="$tmp/e/wear-out-convex.log"
check "$tmp/e" --out "$tmp/e/report" || fail "refused a run short of its schedule: $(cat "$tmp/out")"
grep -q "| 2 of 5 | 560 | .* | in progress or stopped (no log beside the run folder) |" "$tmp/e/report/holder-cases.md" ||
  fail "a run with no log is not told as such: $(grep '^| wear-out' "$tmp/e/report/holder-cases.md")"
printf '=== t0 wearsim run --overwrite c.prm\nstopped by SIGTERM in stage 2 of 6 (revolution 2, t = 1 s); checkpoint written\n' > "$wlog"
printf '=== t1 wearsim run --resume c.prm\nwearsim run: error: wear stage: the worn surface folds at face 7 (label C54); reduce it\n' >> "$wlog"
check "$tmp/e" --out "$tmp/e/report" || fail "refused a run that stopped by an error: $(cat "$tmp/out")"
grep -q "| stopped by an error in stage 4: wear stage: the worn surface folds at face 7 (label C54) |" \
  "$tmp/e/report/holder-cases.md" || fail "the error is not reported: $(grep '^| wear-out' "$tmp/e/report/holder-cases.md")"
printf '=== t2 wearsim run --resume c.prm\nstopped by SIGTERM in stage 4 of 6 (revolution 4, t = 2 s); checkpoint written\n' >> "$wlog"
check "$tmp/e" --out "$tmp/e/report" || fail "refused a stopped run: $(cat "$tmp/out")"
grep -q "| stopped by SIGTERM in stage 4 of 6, continued from its checkpoint by run.sh |" \
  "$tmp/e/report/holder-cases.md" || fail "an earlier call's error outlives a later stop: $(grep '^| wear-out' "$tmp/e/report/holder-cases.md")"

# Element heights from the first and last surfaces: two 6 mm elements on a base top at z = 10 mm
# worn to tops at 12.5 mm (C11) and 9.25 mm (C21, gone below the base top).
mkdir -p "$tmp/e/wear-out-convex/surface"
/usr/bin/python3 - "$tmp/e/wear-out-convex/surface" <<'PY' || fail "cannot write stand-in surfaces"
import sys, h5py, numpy as np
def surface(path, top11, top21):  # C21's feet recede with its top, 1 mm below it
    foot21 = min(10, top21 - 1)
    pts = np.array([[0, 0, 10], [1, 0, 10], [0, 1, top11], [5, 0, foot21], [6, 0, foot21], [5, 1, top21]],
                   float) * 1e-3
    tri = np.array([[0, 1, 2], [3, 4, 5]])
    with h5py.File(path, "w") as h:
        h["points"], h["triangles"] = pts, tri
        h["cell/label"] = np.array([[11], [21]])
        h["cell/cumulative_removed_volume"] = h["cell/wear_depth"] = np.zeros((2, 1))
surface(sys.argv[1] + "/stage_0000.h5", 16, 16)
surface(sys.argv[1] + "/stage_0002.h5", 12.5, 9.25)
PY
check "$tmp/e" --out "$tmp/e/report" || fail "refused a run with surfaces: $(cat "$tmp/out")"
grep -q "Element heights after stage 2: .*(unworn 6.00;" "$tmp/e/report/holder-cases.md" &&
  grep -q "^| 1 | C11 2.50 | C21 -0.75 |" "$tmp/e/report/holder-cases.md" ||
  fail "the element heights are not 2.50 and -0.75 mm: $(grep -A4 'Element heights' "$tmp/e/report/holder-cases.md")"

# A run of another engine, named in the refusal.
run_folder "$tmp/b/stress-plain" e1 1e-7 1.0
run_folder "$tmp/b/wear-out-convex" e2 5e-8 1.0
check "$tmp/b" --check && fail "accepted a run of another engine"
grep -q "wear-out-convex: e2" "$tmp/out" || fail "the refusal does not name the odd run: $(cat "$tmp/out")"

# No run at all.
mkdir -p "$tmp/c"
check "$tmp/c" --check && fail "accepted a root with no run"
grep -q "none of the runs" "$tmp/out" || fail "unclear refusal of an empty root: $(cat "$tmp/out")"

# A run that names no engine version.
run_folder "$tmp/d/stress-convex" e1 5e-8 1.0
sed -i 2d "$tmp/d/stress-convex/parameters.prm"
check "$tmp/d" --check && fail "accepted a run that names no engine version"
grep -q "names no engine version" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"
echo "holder_cases_report_test: passed"
