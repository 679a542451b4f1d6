#!/bin/bash
# cases/reference-study/keep_running.sh and the restore run.sh makes (case_paths.sh,
# restore_running) on a stand-in run: an unfinished run is kept as its compressed checkpoint,
# the index entries of its stage files and its parameters, beside its case file; restored into
# an output folder that holds no run, the checkpoint is the run's at its latest stage's end
# without its bed and its parts' volume meshes (every other object and attribute the same; the one before it when the run
# stopped inside a stage; refused when neither lies at a stage's end) and each stage file a
# stub with the same index entry (a fixed-length string, as wearsim reads it), and the part's
# part_wear.csv, part_life.csv and element_life.csv come back as they were (a resume reads
# their rows); a folder that holds a run is left alone; a checkpoint above CAP_MB is refused and the kept set left as it
# is; a finished run's kept set is deleted.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "keep_running_test: $*" >&2; exit 1; }

prm=$tmp/case/plain.prm out=$tmp/output/plain-run keep=$tmp/case/running/plain-run
part=$out/parts/sample # a tester case's stage files are its part's (wearsim run)
mkdir -p "$tmp/case" "$part/surface" "$part/volume"
printf 'subsection Output\n  set Directory = %s\nend\n' "$out" > "$prm"
printf '# Fully resolved parameters of %s\n# Engine version: e1\n' "$prm" > "$out/parameters.prm"
checkpoint() { # <stages done> [<open duration>]: the stand-in checkpoint of a 3-stage schedule
  # (its bed, one part whose open stage lasts <open duration>, 0 at a stage's end), its stage
  # files, and the checkpoint before it (kept by the run's write) at the previous stage's end
  [ ! -f "$out/checkpoint.h5" ] || mv "$out/checkpoint.h5" "$out/checkpoint.previous.h5"
  /usr/bin/python3 - "$out" "$1" "${2:-0}" <<'PY' || fail "cannot write the stand-in run (python3-h5py)"
import sys, h5py, numpy as np
out, done, duration = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
with h5py.File(out + "/checkpoint.h5", "w") as h:
    h.attrs["stages_done"] = done
    h["parameters"] = np.frombuffer(b"subsection Coupling\n  set Schedule = 1 dem-only, 2 staged\nend\n", dtype=np.int8)
    h["dem/position"] = np.arange(3000.0)
    h["scene/part_0/open_loads/impulse"] = np.zeros((4, 3))
    h["scene/part_0/open_loads/impulse"].attrs["duration"] = duration
    h["scene/part_0/sample/removed_volume"] = np.full(4, 1e-9 * done)
    h["scene/part_0/sample/tetrahedra"] = np.arange(8).reshape(2, 4)  # the volume mesh
    h["scene/part_0/sample/surface/vertices"] = np.zeros((4, 3))
for kind, stage in (("surface", 0), ("surface", 1), ("volume", 1)):
    with h5py.File(f"{out}/parts/sample/{kind}/stage_{stage:04d}.h5", "w") as h:
        h.attrs["xdmf"] = np.bytes_(f"<Grid Name=\"{kind}_{stage}\"/>\n".encode())
        h["points"] = np.zeros((4, 3))
PY
}
same_but_bed() { # <kept checkpoint> <checkpoint>: the first is the second without its bed
  # and its part's volume mesh (the surface kept)
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as k, h5py.File(sys.argv[2], "r") as c:
    assert "dem" not in k and "dem" in c and k.attrs["without_bed"] == 1
    assert k["parameters"].dtype == c["parameters"].dtype
    assert all(k.attrs[a] == c.attrs[a] for a in c.attrs)
    def walk(h):
        found = []
        h.visititems(lambda n, o: found.append(n) if isinstance(o, h5py.Dataset) else None)
        return found
    assert walk(k) == [n for n in walk(c) if not n.startswith("dem") and not n.endswith("/sample/tetrahedra")]
    assert "scene/part_0/sample/surface/vertices" in walk(k)
    assert all(np.array_equal(k[n][()], c[n][()]) for n in walk(k))
    assert k["scene/part_0/open_loads/impulse"].attrs["duration"] == c["scene/part_0/open_loads/impulse"].attrs["duration"]
PY
}
keep() { bash "$root/cases/reference-study/keep_running.sh" "$prm" > "$tmp/out" 2>&1; }

checkpoint 1
printf 'stage,what\n1,part\n' > "$part/part_life.csv"
printf 'stage,label\n1,base\n' > "$part/part_wear.csv"
printf 'stage,what,measured_by\n1,C11,e1\n' > "$part/element_life.csv"
keep || fail "refused an unfinished run: $(cat "$tmp/out")"
[ -f "$keep/checkpoint.h5.xz" ] && [ -f "$keep/parameters.prm" ] && grep -q "1 of 3 stages done, engine e1" "$keep/kept.txt" ||
  fail "the kept set is not complete: $(ls -R "$keep") $(cat "$tmp/out")"
[ "$(ls "$keep/index")" = "$(printf 'parts+sample+surface_stage_0000.xml\nparts+sample+surface_stage_0001.xml\nparts+sample+volume_stage_0001.xml')" ] ||
  fail "the index entries kept are not the three stage files': $(ls "$keep/index")"
cp "$out/checkpoint.h5" "$tmp/checkpoint.orig"
cp "$part/part_life.csv" "$part/part_wear.csv" "$part/element_life.csv" "$tmp/"

rm -rf "$out"
restored=$(cd "$root" && source cases/reference-study/case_paths.sh && restore_running "$prm") ||
  fail "the kept set was not restored"
[ -n "$restored" ] && same_but_bed "$out/checkpoint.h5" "$tmp/checkpoint.orig" ||
  fail "the restored checkpoint is not the run's without its bed"
cmp -s "$tmp/part_life.csv" "$part/part_life.csv" && cmp -s "$tmp/part_wear.csv" "$part/part_wear.csv" &&
  cmp -s "$tmp/element_life.csv" "$part/element_life.csv" ||
  fail "the part's tables did not come back: $(ls -R "$out")"
/usr/bin/python3 - "$out" <<'PY' || fail "the restored stubs do not hold the index entries"
import sys, h5py
for kind, stage in (("surface", 0), ("surface", 1), ("volume", 1)):
    with h5py.File(f"{sys.argv[1]}/parts/sample/{kind}/stage_{stage:04d}.h5", "r") as h:
        t = h.attrs.get_id("xdmf").get_type()
        assert not t.is_variable_str() and h.attrs["xdmf"] == f"<Grid Name=\"{kind}_{stage}\"/>\n".encode()
        assert "points" not in h
PY
printf 'x' > "$part/summary.csv"
again=$(cd "$root" && source cases/reference-study/case_paths.sh && restore_running "$prm") &&
  [ -z "$again" ] || fail "restored into a folder that holds a run: $again"

CAP_MB=0 keep && fail "kept a checkpoint above CAP_MB"
grep -q "above CAP_MB=0" "$tmp/out" && [ -f "$keep/checkpoint.h5.xz" ] || fail "the refusal lost the kept set: $(cat "$tmp/out")"

# Stopped inside stage 2: the checkpoint before it, at the end of stage 1, is kept.
rm -rf "$out"
mkdir -p "$part/surface" "$part/volume"
cp "$tmp/part_life.csv" "$tmp/part_wear.csv" "$part/"
checkpoint 1
cp "$out/checkpoint.h5" "$tmp/checkpoint.end1"
checkpoint 1 0.5
keep || fail "refused a run stopped inside a stage: $(cat "$tmp/out")"
grep -q "checkpoint.previous.h5 kept without its bed" "$tmp/out" && grep -q "1 of 3 stages done" "$keep/kept.txt" ||
  fail "the checkpoint at the stage's end was not the one kept: $(cat "$tmp/out")"
xz -dc "$keep/checkpoint.h5.xz" > "$tmp/kept.h5" && same_but_bed "$tmp/kept.h5" "$tmp/checkpoint.end1" ||
  fail "the kept checkpoint is not the one at the end of stage 1 without its bed"
# Neither checkpoint at a stage's end: refused, the kept set left as it is.
checkpoint 1 0.7
keep && fail "kept a checkpoint written inside a stage"
grep -q "lies at a stage's end" "$tmp/out" && [ -f "$keep/checkpoint.h5.xz" ] ||
  fail "the refusal does not say why or lost the kept set: $(cat "$tmp/out")"

checkpoint 3
keep || fail "refused a finished run: $(cat "$tmp/out")"
[ ! -d "$keep" ] && grep -q "finished (3 of 3 stages)" "$tmp/out" || fail "a finished run's kept set stays: $(cat "$tmp/out")"
echo "keep_running_test: passed"
