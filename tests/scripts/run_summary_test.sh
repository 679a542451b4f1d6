#!/bin/bash
# docs/results/run_summary.py on a stand-in run folder: the per-revolution wear reads back to
# the same floats as history.h5 holds, the map's centroids within 5 um and the profiles within
# 0.05 um of the surfaces', the element extents exactly; the log's last call is told in
# ending.txt and the last surface's stage in run.txt. A run continued from a kept checkpoint
# (its stage-0 surface an index stub) keeps the stage-0 parts of the summary it replaces; a
# run without a checkpoint does not replace the summary of the same case that went further,
# one with a checkpoint does; a folder that is no run is refused.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
summary="$root/docs/results/run_summary.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "run_summary_test: $*" >&2; exit 1; }

# The stand-in: 3 revolutions, 2 stages; a sample of a base (label 3) and elements C11 and C13
# (triangles in planes x = const and z = const), its stage-2 surface worn 0.5 mm off C13's top.
# The run folder as `wearsim run` writes a tester case: parameters.prm at its top, the tables
# and surfaces in parts/sample/.
run=$tmp/output/convex
tab=$run/parts/sample
mkdir -p "$tab/surface"
printf '# Fully resolved parameters of cases/reference-study/convex.prm\n# Engine version: e1\n  set Schedule = 1 dem-only, 1 staged\n' > "$run/parameters.prm"
printf 'revolution,wear_volume_m3\n1,7e-08\n2,7.1e-08\n3,7.2e-08\n' > "$tab/summary.csv"
printf 'stage,scheme_name,first_revolution\n1,dem-only,1\n2,staged,2\n' > "$tab/stages.csv"
printf '=== t0 wearsim run --overwrite c.prm\nstopped by SIGTERM in stage 2 of 2 at t = 4 s after a checkpoint; continue with wearsim run --resume c.prm\n' > "$run.log"
/usr/bin/python3 - "$tab" <<'PY' || fail "cannot write the stand-in run (python3-h5py)"
import sys, h5py, numpy as np
run = sys.argv[1]
rng = np.random.default_rng(1)
with h5py.File(run + "/history.h5", "w") as h:
    g = h.create_group("revolutions")
    g["revolution"] = np.array([1.0, 2.0, 3.0])
    g["column_wear_m3"] = rng.random((3, 5)) * 1e-8
    g["element_labels"] = np.array([11, 13], dtype=np.int32)
    g["element_wear_m3"] = rng.random((3, 2)) * 1e-9 / 3
def surface(path, top13):
    pts = np.array([[-0.05, -0.06, 0.01], [0.05, -0.06, 0.01], [0.05, 0.06, 0.01], [-0.05, 0.06, 0.01],
                    [-0.04, -0.045, 0.01], [-0.04, -0.035, 0.01], [-0.04, -0.04, 0.016],
                    [0.0, -0.045, 0.01], [0.0, -0.035, 0.01], [0.0, -0.04, top13]])
    pts[4:, 0] += rng.random(6) * 1e-9  # not exactly on the cutting planes
    tri = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [7, 8, 9]])
    with h5py.File(path, "w") as h:
        h["points"], h["triangles"] = pts, tri
        h["cell/label"] = np.array([[3], [3], [11], [13]])
        h["cell/cumulative_removed_volume"] = np.zeros((4, 1))
        h["cell/wear_depth"] = np.array([[0.0], [0.0], [1e-4], [5e-4]])
        h.attrs["xdmf"] = np.bytes_(b"<Grid/>")
surface(run + "/surface/stage_0000.h5", 0.016)
surface(run + "/surface/stage_0002.h5", 0.0155)
PY
/usr/bin/python3 "$summary" "$run" "$tmp/results/convex" > "$tmp/out" 2>&1 || fail "refused the stand-in: $(cat "$tmp/out")"
/usr/bin/python3 - "$root/docs/results" "$run" "$tmp/results/convex" <<'PY' || fail "the summary does not read back"
import sys, h5py, numpy as np
sys.path.insert(0, sys.argv[1])
import run_summary as S
run, s = sys.argv[2:]
labels, elements, columns = S.read_revolutions(s)
with h5py.File(run + "/parts/sample/history.h5") as h:
    assert labels == [11, 13], labels
    assert np.array_equal(columns, h["revolutions/column_wear_m3"][:]), "column wear not exact"
    assert np.array_equal(elements, h["revolutions/element_wear_m3"][:]), "element wear not exact"
first, last = S.read_surface(run, 0), S.read_surface(run, 2)
c, lab = S.read_map(s)
pts, tri, flab, _ = first
exact = pts[tri].mean(axis=1)[:, :2]
for k in (3, 11, 13):  # sorted within a label: compare as sets of points
    a, b = np.sort(c[lab == k], axis=0), np.sort(exact[flab == k], axis=0)
    assert np.abs(a - b).max() <= 5e-6, ("map", k)
lines = S.read_profiles(s)
assert [n for n, _, _ in lines] == ["C13", "C11"], lines
for name, x0, cuts in lines:
    assert sorted(cuts) == [0, 2], cuts.keys()
    for stage, surf in ((0, first), (2, last)):
        y, z, d = S.section(surf, x0)
        got = cuts[stage]
        assert len(got[0]) == len(y) > 0 and max(np.abs(got[0] - y).max(), np.abs(got[1] - z).max()) <= 5e-8, (name, stage)
top = S.read_elements(s)
assert top[0][13] == (0.016, 0.01) and top[2][13] == (0.0155, 0.01), top
info = S.read_run_txt(s)
assert info["last surface"] == "2" and info["engine"] == "e1", info
assert open(s + "/ending.txt").read() == "stopped by SIGTERM in stage 2 of 2\n"
PY

# Continued from a kept checkpoint: the stage-0 surface an index stub, a stage-3 surface worn on.
cp -r "$tmp/results/convex" "$tmp/first"
/usr/bin/python3 - "$tab" <<'PY' || fail "cannot write the stub"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1] + "/surface/stage_0000.h5", "w") as h:
    h.attrs["xdmf"] = np.bytes_(b"<Grid/>")
PY
cp "$tab/surface/stage_0002.h5" "$tab/surface/stage_0003.h5"
printf '4,7.3e-08\n' >> "$tab/summary.csv"
rm "$run.log"
/usr/bin/python3 "$summary" "$run" "$tmp/results/convex" > "$tmp/out" 2>&1 || fail "refused a continued run: $(cat "$tmp/out")"
cmp -s "$tmp/first/surface_map.txt" "$tmp/results/convex/surface_map.txt" || fail "the map of stage 0 was not kept"
[ "$(grep -c ',0,' "$tmp/first/profiles.csv")" -eq "$(grep -c ',0,' "$tmp/results/convex/profiles.csv")" ] &&
  grep ',0,' "$tmp/first/profiles.csv" | cmp -s - <(grep ',0,' "$tmp/results/convex/profiles.csv") ||
  fail "the stage-0 profiles were not kept"
grep -q '^11,0,' "$tmp/results/convex/elements.csv" && grep -q '^13,3,0.0155,' "$tmp/results/convex/elements.csv" ||
  fail "the element extents of stages 0 and 3 are not there: $(cat "$tmp/results/convex/elements.csv")"
grep -q "^last surface: 3$" "$tmp/results/convex/run.txt" || fail "the last surface is not stage 3"
[ ! -f "$tmp/results/convex/ending.txt" ] || fail "ending.txt written without a log"
rm -rf "$tmp/nosummary"
/usr/bin/python3 "$summary" "$run" "$tmp/nosummary" > "$tmp/out" 2>&1 &&
  fail "summarised a run whose stage-0 surface is a stub with no summary to take it from"
grep -q "holds no surface" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"

# A run that cannot be continued (no checkpoint) and got less far does not replace the summary
# of its case; with a checkpoint it does.
head -n 3 "$tab/summary.csv" > "$tab/summary.short" && mv "$tab/summary.short" "$tab/summary.csv"
/usr/bin/python3 "$summary" "$run" "$tmp/results/convex" > "$tmp/out" 2>&1 || fail "refused: $(cat "$tmp/out")"
grep -q "kept: its run went further" "$tmp/out" && grep -q "^revolutions: 4$" "$tmp/results/convex/run.txt" ||
  fail "a shorter run without a checkpoint replaced the summary: $(cat "$tmp/out")"
touch "$run/checkpoint.h5"
/usr/bin/python3 "$summary" "$run" "$tmp/results/convex" > "$tmp/out" 2>&1 || fail "refused: $(cat "$tmp/out")"
grep -q "^revolutions: 2$" "$tmp/results/convex/run.txt" || fail "a checkpointed run did not replace the summary"

# No run folder.
mkdir -p "$tmp/empty"
/usr/bin/python3 "$summary" "$tmp/empty" "$tmp/results/empty" > "$tmp/out" 2>&1 && fail "summarised an empty folder"
grep -q "is '$tmp/empty' a wearsim run folder" "$tmp/out" || fail "unclear refusal: $(cat "$tmp/out")"
echo "run_summary_test: passed"
