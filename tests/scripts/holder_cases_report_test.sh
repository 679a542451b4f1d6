#!/bin/bash
# docs/results/holder_cases_report.py reports the wear-out and stress runs it finds and lists
# the others as not run; it refuses a root with none of them, a run of another engine version
# than its study's (each pair its own ENGINE file) and a run that names none. Its arithmetic is checked
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

# The wear-out pair's life and ratio: the convex sample wears half the plain one's DEM wear in
# both staged stages (ratio 0.500 a revolution and cumulative); its two elements of 100 mm^3
# keep 70 % after 280 h and 25 % after 560 h, so half is gone at 280 + 280 x 0.2 / 0.45 = 404 h,
# and one element (1 mm) of the two still stands above the 0.25 mm vanish height; the run ended
# worn out, as its log says.
run_folder "$tmp/f/wear-out-convex" e1 5e-8 1.0
run_folder "$tmp/f/wear-out-plain" e1 1e-7 1.0
printf 'stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3\n%s\n' \
  "1,0,0,C11,0.006,1e-07
1,0,0,C21,0.006,1e-07
1,0,0,part,0.01,1e-05
2,10,280,C11,0.004,8e-08
2,10,280,C21,0.003,6e-08
2,10,280,part,0.0095,9.9e-06
3,20,560,C11,0.001,3e-08
3,20,560,C21,0.0002,2e-08
3,20,560,part,0.009,9.8e-06" > "$tmp/f/wear-out-convex/part_life.csv"
printf 'stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3\n1,0,0,part,0.01,1e-05\n3,20,560,part,0.008,9e-06\n' \
  > "$tmp/f/wear-out-plain/part_life.csv"
printf '=== t0 wearsim run --overwrite c.prm\npart '"'"'sample'"'"' worn out at 560 h after stage 3: no convex element stands higher than 0.25 mm above its foot (Coupling/Worn out when = elements gone)\n' \
  > "$tmp/f/wear-out-convex.log"
sed -i 's/2 staged/5 staged/' "$tmp/f/wear-out-convex/parameters.prm"
check "$tmp/f" --out "$tmp/f/report" || fail "refused the wear-out pair: $(cat "$tmp/out")"
md="$tmp/f/report/holder-cases.md"
[ -f "$tmp/f/report/wear_out.png" ] || fail "wrote no wear_out.png"
grep -q "| worn out at 560 h after stage 3: no convex element stands higher than 0.25 mm above its foot |" "$md" ||
  fail "the worn-out end is not told: $(grep '^| wear-out-convex' "$md")"
grep -q "^| 3 | 560 | 1 | 50 | 25.0 | 1.00 / 0.20 | 9.00 | 8.00 |" "$md" ||
  fail "the life after stage 3 is not 1 standing, 50 mm^3, 25 %: $(grep -A5 'pattern' "$md")"
grep -q "^| 2 | 280 | 2 | 140 | 70.0 | 4.00 / 3.00 | 9.50 | 9.00 |" "$md" ||
  fail "the life after stage 2 (plain interpolated at 280 h: 9.00 mm) is wrong: $(grep -A5 'pattern' "$md")"
grep -q "Half the element volume gone\*\* at 404 h" "$md" || fail "half the volume is not gone at 404 h: $(grep 'Half' "$md")"
grep -q "^| 3 | 280 | 50.00 | 100.00 | 0.500 |" "$md" || fail "the ratio a revolution is not 0.500: $(grep -A6 'Convex / plain' "$md")"
grep -q "convex / plain 0.500\*\*" "$md" || fail "the cumulative ratio is not 0.500: $(grep '^Over the first' "$md")"
# The convergence runs: at A/2 half the element volume is gone at 560 h, 38.5 % after the
# 404 h of the wear-out run's first stages again (convex-stages.prm), its elements 100 mm^3 on
# the first mesh, 70 mm^3 removed from their labels by then (part_wear.csv); the run at h/2 is
# not run. On the unworn footprints (element_life.csv) the first stages keep 60 % after 280 h
# and 20 % after 560 h: half gone at 280 + 280 x 0.1 / 0.4 = 350 h; A/2 at 560 h, +60.0 %.
cp -r "$tmp/f/wear-out-convex" "$tmp/f/wear-out-convex-stages"
printf 'stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3,measured_by\n%s\n' \
  "1,0,0,C11,0.006,1e-07,v9
2,10,280,C11,0.004,6e-08,v9
3,20,560,C11,0.001,2e-08,v9" > "$tmp/f/wear-out-convex-stages/element_life.csv"
run_folder "$tmp/f/wear-out-convex-a10" e1 5e-8 1.0
printf 'stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3,measured_by\n%s\n' \
  "1,0,0,C11,0.006,1e-07,v9
3,20,560,C11,0.002,5e-08,v9" > "$tmp/f/wear-out-convex-a10/element_life.csv"
printf 'stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3\n%s\n' \
  "1,0,0,C11,0.006,1e-07
1,0,0,part,0.01,1e-05
3,20,560,C11,0.002,5e-08
3,20,560,part,0.009,9.8e-06" > "$tmp/f/wear-out-convex-a10/part_life.csv"
printf 'stage,scheme,time_s,label,stage_volume_m3,cumulative_removed_volume_m3\n%s\n' \
  "3,staged,1,C11,7e-08,7e-08
3,staged,1,base,1e-07,1e-07" > "$tmp/f/wear-out-convex-a10/part_wear.csv"
check "$tmp/f" --out "$tmp/f/report" || fail "refused the convergence runs: $(cat "$tmp/out")"
grep -q "^| wear-out-convex-a10 | h, A/2 | .* | 100 | 560 | +38.5 % against wear-out-convex-stages | 70 | 560 | +60.0 % against wear-out-convex-stages |" "$md" ||
  fail "the convergence at A/2 is not +38.5 % and +60.0 %: $(grep -A8 'Convergence' "$md")"
grep -q "^| wear-out-convex-stages | h, A | .* | 404 |  |  | 350 |  |" "$md" ||
  fail "half is not gone at 404 h and 350 h in the first stages: $(grep -A8 'Convergence' "$md")"
grep -q "measured by \`wearsim life\` of engine v9" "$md" || fail "the measuring engine is not named"
grep -q "^| wear-out-convex-fine | h/2, A | .* | not run | |" "$md" ||
  fail "the run at h/2 is not listed as not run: $(grep -A6 'Convergence' "$md")"

# Each pair its study's engine: without --engine a wear-out run of the reference study's engine
# is refused (the wear-out pair's is cases/wear-out/ENGINE).
ref=$(cat "$root/cases/reference-study/ENGINE")
own=$(cat "$root/cases/wear-out/ENGINE")
if [ "$ref" != "$own" ]; then
  run_folder "$tmp/g/stress-plain" "$ref" 1e-7 1.0
  run_folder "$tmp/g/wear-out-convex" "$ref" 5e-8 1.0
  summarise_stand_ins "$tmp/g"
  /usr/bin/python3 "$report" --root "$tmp/g.summaries" --check > "$tmp/out" 2>&1 &&
    fail "accepted a wear-out run of the reference study's engine"
  grep -q "wear-out-convex: $ref, not $own" "$tmp/out" && ! grep -q "stress-plain:" "$tmp/out" ||
    fail "the refusal does not name the wear-out run alone: $(cat "$tmp/out")"
fi

# A run of another engine, named in the refusal.
run_folder "$tmp/b/stress-plain" e1 1e-7 1.0
run_folder "$tmp/b/wear-out-convex" e2 5e-8 1.0
check "$tmp/b" --check && fail "accepted a run of another engine"
grep -q "wear-out-convex: e2, not e1" "$tmp/out" || fail "the refusal does not name the odd run: $(cat "$tmp/out")"

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
