#!/usr/bin/env bash
# Keeps in the repository what an unfinished run of the study needs to continue on another
# machine, so that a study longer than a working session goes on in the next one (run.sh
# restores it into an output folder that holds no run of its case). Per run,
# cases/<case>/running/<run>/ (case_paths.sh), replaced in place at every call, holds:
#   checkpoint.h5.xz   the run's checkpoint at its latest stage's end without the particle
#                      bed and without the parts' volume meshes, xz-compressed: each worn
#                      surface with its wear fields, the per-face stress of the last stage and
#                      every revolution and stage record (a few hundred kB). The resume meshes
#                      each part from its surface, fills the bed anew on the worn surfaces and
#                      runs it for the schedule's leading dem-only stages before the next
#                      stage (docs/user-guide.md, "Runs longer than a session"): the
#                      particles' state would take 5 MB a run, a worn part's tetrahedra 0.5
#   index/<folder>_stage_NNNN.xml
#                      the index entry (the "xdmf" attribute) of each surface/ and volume/
#                      stage file of each part (<folder> its folder in the run, "/" as "+":
#                      parts+sample+surface): the one thing a resume reads of them (it
#                      re-lists every stage in history.xdmf); run.sh writes them back as stubs
#   parameters.prm     the run's resolved parameters (its engine version and schedule)
#   tables/<part>+<file>
#                      each part's part_wear.csv, part_life.csv and element_life.csv: rows
#                      a resume keeps from the file it finds and does not rebuild from the
#                      checkpoint
#   kept.txt           one line: the stages done of those planned, the engine, when kept
# Nothing else: no volume or surface fields, no VTU, no history.h5, summary.csv or stages.csv
# (the resumed run rewrites those from the checkpoint's records after its next stage; its
# summary in cases/<case>/results keeps the stage-0 surface's parts, run_summary.py).
# A finished run's folder is deleted: its summary is what stays. A run without a checkpoint
# (the node-moving scheme keeps none) has nothing to keep and starts afresh.
# Call it when the runs have stopped (run.sh returned), then commit cases/*/running and
# cases/*/results.
#
# usage: bash cases/reference-study/keep_running.sh [case ...]
#        case: as for run.sh (default: every case here and in cases/wear-out and cases/stress
#              whose output folder exists)
#        CAP_MB=<n>: refuse a compressed checkpoint above n MB (default 1, the cap of every
#        file in the repository, tests/scripts/file_sizes_test.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
source cases/reference-study/case_paths.sh
cap_mb=${CAP_MB:-1}

stages_of() { # <checkpoint>: "<stages done> <stages planned>" from the checkpoint itself
  /usr/bin/python3 - "$1" <<'EOF'
import re, sys, h5py
with h5py.File(sys.argv[1], "r") as h:
    done = int(h.attrs["stages_done"])
    # the resolved case: a dataset of bytes, an attribute from older engines
    text = h["parameters"][()].tobytes() if "parameters" in h else h.attrs["parameters"]
text = text.decode() if isinstance(text, bytes) else str(text)
schedule = re.search(r"^\s*set Schedule\s*=\s*([^#\n]*)", text, re.M)
print(done, sum(int(n) for n in re.findall(r"\d+", schedule.group(1))) if schedule else 0)
EOF
}

without_bed() { # <run folder> <file>: its checkpoint at the latest stage's end without the
  # particle bed (/dem left out, the root's attribute without_bed = 1) and without each part's
  # volume mesh (scene/part_<k>/sample/{vertices,tetrahedra,boundary_faces,boundary_ids}: the
  # resume meshes it from the kept surface); every other object and attribute as written:
  # checkpoint.h5, or checkpoint.previous.h5 when the latest lies inside a stage; refused when
  # neither lies at a stage's end
  /usr/bin/python3 - "$1" "$2" <<'EOF'
import os, sys, h5py, numpy as np
run, kept = sys.argv[1:]
VOLUME_MESH = ("vertices", "tetrahedra", "boundary_faces", "boundary_ids")
def at_stage_end(h):
    scene = h["scene"]
    return all(scene[p]["open_loads/impulse"].attrs["duration"] == 0
               for p in scene if p.startswith("part_"))
def copy_attributes(src, dst):  # each with its own type (fixed-length strings stay so)
    for key in src.attrs:
        dst.attrs.create(key, src.attrs[key], dtype=src.attrs.get_id(key).dtype)
def left_out(path):  # the bed, and a part's volume mesh: scene/part_<k>/sample/<array>
    parts = path.split("/")
    return parts[0] == "dem" or (len(parts) == 4 and parts[0] == "scene" and
                                 parts[1].startswith("part_") and parts[2] == "sample" and
                                 parts[3] in VOLUME_MESH)
for name in ("checkpoint.h5", "checkpoint.previous.h5"):
    try:
        src = h5py.File(f"{run}/{name}", "r")
    except OSError:
        continue
    with src:
        if not at_stage_end(src):
            continue
        with h5py.File(kept, "w") as dst:
            copy_attributes(src, dst)
            dst.attrs["without_bed"] = np.float64(1)
            def keep(path, obj):
                if left_out(path):
                    return
                if isinstance(obj, h5py.Group):
                    copy_attributes(obj, dst.require_group(path))
                else:
                    src.copy(obj, dst[os.path.dirname(path) or "/"], name=os.path.basename(path))
            src.visititems(keep)
        print(f"keep_running.sh: {run}/{name} kept without its bed", file=sys.stderr)
        sys.exit(0)
sys.exit(f"keep_running.sh: neither checkpoint of {run} lies at a stage's end (let the run "
         "finish its stage, or stop it by a signal right after one)")
EOF
}

index_entries() { # <run folder> <index folder>: each stage file's index entry as text, named
  # after its folder in the run ("/" as "+": parts+sample+surface_stage_0001.xml for a part's)
  /usr/bin/python3 - "$1" "$2" <<'EOF'
import glob, os, sys, h5py
run, index = sys.argv[1:]
os.makedirs(index)
for base in [run] + sorted(glob.glob(os.path.join(run, "parts", "*"))):
    for kind in ("surface", "volume"):
        d = os.path.join(base, kind)
        prefix = os.path.relpath(d, run).replace(os.sep, "+")
        for name in sorted(os.listdir(d)) if os.path.isdir(d) else []:
            if name.startswith("stage_") and name.endswith(".h5"):
                with h5py.File(os.path.join(d, name), "r") as h:
                    entry = h.attrs["xdmf"]
                with open(os.path.join(index, f"{prefix}_{name[:-3]}.xml"), "wb") as f:
                    f.write(entry if isinstance(entry, bytes) else str(entry).encode())
EOF
}

part_tables() { # <run folder> <tables folder>: each part's part_wear.csv, part_life.csv and
  # element_life.csv
  local t
  mkdir -p "$2" || return 1
  for t in "$1"/parts/*/part_wear.csv "$1"/parts/*/part_life.csv "$1"/parts/*/element_life.csv; do
    [ -f "$t" ] || continue
    cp "$t" "$2/$(basename "$(dirname "$t")")+$(basename "$t")" || return 1
  done
}

keep_one() { # <case>: its run's resume set into running_dir, or that deleted when it finished
  local out keep new done planned engine params
  out=$(out_dir "$1") keep=$(running_dir "$1")
  params=$out/parameters.prm # a folder restored and not yet resumed has only the kept one
  [ -f "$params" ] || params=$keep/parameters.prm
  if [ ! -f "$out/checkpoint.h5" ]; then
    local left=""
    [ ! -d "$keep" ] || left="; $keep left as it is"
    echo "keep_running.sh: $1: no checkpoint in $out, nothing to keep$left"
    return 0
  fi
  read -r done planned < <(stages_of "$out/checkpoint.h5") && [ -n "${planned:-}" ] ||
    { echo "keep_running.sh: $1: cannot read $out/checkpoint.h5" >&2; return 1; }
  if [ "$planned" -gt 0 ] && [ "$done" -ge "$planned" ]; then
    rm -rf "$keep"
    rmdir --ignore-fail-on-non-empty "$(dirname "$keep")" 2> /dev/null || true
    echo "keep_running.sh: $1: finished ($done of $planned stages); $keep deleted (its summary stays)"
    return 0
  fi
  # built beside the kept set and put in its place only when complete (set -e does not hold
  # in a function whose status is tested, hence the checks)
  new="$(dirname "$keep")/.$(basename "$keep").new"
  rm -rf "$new"
  mkdir -p "$new" && index_entries "$out" "$new/index" && cp "$params" "$new/parameters.prm" &&
    part_tables "$out" "$new/tables" &&
    without_bed "$out" "$new/checkpoint.h5" &&
    read -r done planned < <(stages_of "$new/checkpoint.h5") &&
    nice xz -6 -T1 "$new/checkpoint.h5" ||
    { echo "keep_running.sh: $1: cannot write $new; $keep left as it is" >&2; rm -rf "$new"; return 1; }
  if [ "$(stat -c %s "$new/checkpoint.h5.xz")" -gt $((cap_mb * 1048576)) ]; then
    echo "keep_running.sh: $1: the compressed checkpoint is $(du -m "$new/checkpoint.h5.xz" | cut -f1) MB, above CAP_MB=$cap_mb; $keep left as it is" >&2
    rm -rf "$new"
    return 1
  fi
  engine=$(sed -n 2p "$params" | sed 's/^# Engine version: //')
  echo "$(run_name "$1"): $done of $planned stages done, engine $engine, kept $(date -u +%FT%TZ)" > "$new/kept.txt"
  rm -rf "$keep" && mv "$new" "$keep" || { echo "keep_running.sh: $1: cannot replace $keep" >&2; return 1; }
  echo "keep_running.sh: $(cat "$keep/kept.txt") in $keep ($(du -sh "$keep" | cut -f1))"
}

cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
  for f in cases/reference-study/*.prm cases/wear-out/*.prm cases/stress/*.prm; do
    c=$f
    [ "$(dirname "$f")" = cases/reference-study ] && c=$(basename "$f" .prm)
    [ "$c" = calibration ] && continue
    [ -d "$(out_dir "$c")" ] && cases+=("$c")
  done
fi
status=0
for c in "${cases[@]}"; do
  [ -f "$(case_file "$c")" ] || { echo "keep_running.sh: no case file $(case_file "$c")" >&2; exit 2; }
  keep_one "$c" || status=1
done
exit $status
