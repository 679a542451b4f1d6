#!/bin/bash
# docs/results/shape_study_report.py reports the clumps' runs beside the reference study's
# spheres (the repository's own summaries, cases/reference-study/results). Its arithmetic is
# checked on stand-in clumps' summaries with known figures: a plain sample wearing 100 mm^3 and
# a convex one 40 mm^3 a revolution give convex / plain 0.400 at 56 h; seeds of ratios 0.400
# and 0.360 give 0.380 +- 0.254 (Student t, 1 degree of freedom: 12.706 x 0.02 / sqrt 2 x
# sqrt 2), and against the repository's spheres at s = 3 (mean 0.447, variance 3.74e-5) a
# difference of -0.067 +- 0.258 (Welch: 12.706 x sqrt(0.0008 / 2 + 3.74e-5 / 3), 1 degree of
# freedom), which cannot tell the two apart, and the spheres' 0.519 at s = 4 lies inside the
# clumps' interval 0.126 to 0.634; columns of 10 to 30 mm^3 and forces of 1 to 5 N give
# 5 / 1 = 3.00 and 5.00, and an element C51 of 6 mm^3 in a column of 12 leaves its base strip
# 6. It refuses clumps' runs that ran spheres, a clumps' run of another engine version, and a
# calibration whose coefficient the runs do not use.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
report="$root/docs/results/shape_study_report.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "shape_study_report_test: $*" >&2; exit 1; }

summary() { # <folder> <engine> <wear a revolution [mm^3]> <convex|plain|calibration> [shape]
  /usr/bin/python3 - "$@" <<'PY' || fail "cannot write the stand-in summary $1"
import os, sys
folder, engine, wear, kind = sys.argv[1:5]
shape = sys.argv[5] if len(sys.argv) > 5 else "crushed stone 4"
wear = float(wear) * 1e-9
os.makedirs(folder, exist_ok=True)
staged = kind != "calibration"
with open(os.path.join(folder, "parameters.prm"), "w") as f:
    f.write(f"# Fully resolved parameters of cases/shape-study/{os.path.basename(folder)}.prm\n"
            f"# Engine version: {engine}\n  set Particle shape = {shape}\n  set Scaling factor = 4\n"
            "  set Archard coefficient = 1e-08\n  set Schedule = 3 dem-only, 2 staged\n")
columns = [c * 1e-9 * (0.4 if kind == "convex" else 1) for c in (10, 15, 20, 25, 30)]
elements = {"C11": 2e-9, "C51": 6e-9} if kind == "convex" else {}
head = (["revolution", "wear_volume_m3", "steady_revolution", "normal_force_mean_N", "bottom_speed_mean_m_s",
         "bottom_spin_mean_rad_s", "bottom_count", "speed_over_sample_mean_m_s", "bed_height_mean_m", "wall_seconds"]
        + [f"column{k}_force_mean_N" for k in range(1, 6)])
with open(os.path.join(folder, "summary.csv"), "w") as f:
    f.write(",".join(head) + "\n")
    for n in range(1, 6):
        f.write(",".join(str(x) for x in [n, wear, 3 if n >= 3 else 0, 15, 0.3, 10, 180, 0.45, 0.11, 600,
                                          1, 2, 3, 4, 5]) + "\n")
with open(os.path.join(folder, "revolutions.csv"), "w") as f:
    f.write(",".join(["revolution"] + [f"column{k}_wear_m3" for k in range(1, 6)]
                     + [f"{e}_wear_m3" for e in elements]) + "\n")
    for n in range(1, 6):
        f.write(",".join(str(x) for x in [n] + columns + list(elements.values())) + "\n")
if staged:
    with open(os.path.join(folder, "stages.csv"), "w") as f:
        f.write("stage,scheme_name,first_revolution,amplification\n")
        for n in range(1, 6):
            f.write(f"{n},{'dem-only' if n <= 3 else 'staged'},{n},1\n")
else:
    with open(os.path.join(folder, "calibration.prm"), "w") as f:
        f.write("subsection Wear law\n  set Model = archard\n  set Archard coefficient = 1e-08\nend\n")
with open(os.path.join(folder, "run.txt"), "w") as f:
    f.write(f"engine: {engine}\nlast surface: none\n")
PY
}
check() { # <runs> [--check]: the report on them beside the repository's spheres, output in $tmp/out
  local r=$1
  shift
  /usr/bin/python3 "$report" --runs "$r" --spheres "$root/cases/reference-study/results" --out "$r.report" "$@" \
    > "$tmp/out" 2>&1
}

summary "$tmp/a/plain" e1 100 plain
summary "$tmp/a/convex" e1 40 convex
summary "$tmp/a/plain-seed2" e1 100 plain
summary "$tmp/a/convex-seed2" e1 36 convex
summary "$tmp/a/calibration-plain" e1 50 calibration
check "$tmp/a" || fail "refused a complete set: $(cat "$tmp/out")"
md="$tmp/a.report/shape-study.md"
[ -f "$md" ] && [ -f "$tmp/a.report/shape_study.png" ] || fail "wrote no report or no plot"
grep -q "^| 56 h (2 revolutions) | 200.00 | 80.00 | 0.400 | 0.519 | 0.454 |" "$md" ||
  fail "convex / plain at 56 h is not 0.400 beside the spheres' 0.519 and 0.454: $(grep '^| 56 h' "$md")"
grep -q "^| 184 h (6.57 revolutions) | n/a | n/a | not reached | not run | 0.446 |" "$md" ||
  fail "184 h is not told as not reached: $(grep '^| 184 h' "$md")"
grep -q "clumps, s = 4: convex / plain per seed 0.400, 0.360; mean \*\*0.380 +- 0.254\*\*" "$md" ||
  fail "the seeds' interval is not 0.380 +- 0.254: $(grep '^- clumps' "$md")"
grep -q "clumps (s = 4) minus spheres (s = 3): \*\*-0.067 +- 0.258\*\* .*1 degree of freedom.*cannot be told apart" "$md" ||
  fail "the clumps' difference to the spheres is not -0.067 +- 0.258: $(grep 'minus spheres' "$md")"
grep -q "spheres at s = 4 (one seed): 0.519, inside the clumps' interval 0.126 to 0.634" "$md" ||
  fail "the spheres at s = 4 are not placed inside the clumps' interval: $(grep 'one seed' "$md")"
grep -q "^| plain | clumps | wear \[mm^3\] | 10.00 | 15.00 | 20.00 | 25.00 | 30.00 | 3.00 |" "$md" &&
  grep -q "^| plain | clumps | normal force \[N\] | 1.00 | 2.00 | 3.00 | 4.00 | 5.00 | 5.00 |" "$md" ||
  fail "the plain columns are not 10 to 30 mm^3 and 1 to 5 N: $(grep '^| plain | clumps' "$md")"
grep -q "^| convex | clumps | of it the base strip \[mm^3\] | 2.00 | 6.00 | 8.00 | 10.00 | 6.00 | 3.00 |" "$md" ||
  fail "the convex base strips are wrong: $(grep 'base strip' "$md")"
grep -q "Not run.* plain-seed3, convex-seed3" "$md" || fail "the seeds not run are not listed"
grep -q "clumps / spheres 1.378" "$md" || fail "the coefficients' ratio is not 1e-8 / 7.258e-9: $(grep '^The plain' "$md")"

# Clumps' runs that ran spheres.
summary "$tmp/b/plain" e1 100 plain sphere
summary "$tmp/b/convex" e1 40 convex
check "$tmp/b" && fail "accepted a clumps' run of spheres"
grep -q "b/plain' ran spheres" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"

# A clumps' run of another engine version.
summary "$tmp/c/plain" e1 100 plain
summary "$tmp/c/convex" e2 40 convex
check "$tmp/c" && fail "accepted runs of two engines"
grep -q "different engine versions" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"

# A calibration that calibrated another coefficient than the runs use.
summary "$tmp/d/plain" e1 100 plain
summary "$tmp/d/convex" e1 40 convex
summary "$tmp/d/calibration-plain" e1 50 calibration
sed -i 's/= 1e-08/= 2e-08/' "$tmp/d/calibration-plain/calibration.prm"
check "$tmp/d" && fail "accepted a calibration the runs do not use"
grep -q "include cases/shape-study/results/calibration-plain/calibration.prm in" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"
echo "shape_study_report_test: passed"
