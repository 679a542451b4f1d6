# Where a case of the reference study's scripts lives (run.sh, keep_running.sh): its case file,
# its output folder, its summary and its kept checkpoint, and how a kept checkpoint comes back.
# Sourced, not run.
# A case is the name of a case file in cases/reference-study without .prm (its output folder
# output/reference-study/<name>), or the path of another case file run by the study's engine,
# such as cases/wear-out/convex.prm, whose output folder is the `set Directory` written in the
# file itself. The run is named after its output folder; its summary and its kept checkpoint
# live beside its case file: cases/<case>/results/<run> and cases/<case>/running/<run>.

case_file() { # <case>: its case file
  case "$1" in *.prm) echo "$1" ;; *) echo "cases/reference-study/$1.prm" ;; esac
}

out_dir() { # <case>: its output folder
  case "$1" in
    *.prm) sed -n 's/^[[:space:]]*set[[:space:]]\+Directory[[:space:]]*=[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$1" | tail -n 1 ;;
    *) echo "output/reference-study/$1" ;;
  esac
}

run_name() { # <case>: the name of its run (its output folder's)
  basename "$(out_dir "$1")"
}

summary_dir() { # <case>: its run's summary (docs/results/run_summary.py), read by the reports
  echo "$(dirname "$(case_file "$1")")/results/$(run_name "$1")"
}

running_dir() { # <case>: its unfinished run's kept checkpoint (keep_running.sh)
  echo "$(dirname "$(case_file "$1")")/running/$(run_name "$1")"
}

holds_run() { # <folder>: whether a run has written its tables or a checkpoint there (as wearsim
  # judges it: coupling/loop/run_folder.cc)
  local f
  for f in "$1"/{stages.csv,summary.csv,scene_series.csv,checkpoint.h5,checkpoint.previous.h5} \
    "$1"/parts/*/{stages.csv,summary.csv}; do
    [ -f "$f" ] && return 0
  done
  return 1
}

summarise() { # <case>: its run's summary written from its output folder, when that has tables
  # (a tester case's are its part's, parts/sample/)
  local out
  out=$(out_dir "$1")
  [ -f "$out/summary.csv" ] || [ -f "$out/parts/sample/summary.csv" ] || return 0
  /usr/bin/python3 docs/results/run_summary.py "$out" "$(summary_dir "$1")"
}

restore_running() { # <case>: its kept checkpoint into its output folder when that holds no run;
  # prints what it restored, nothing when there was nothing to restore; fails when it cannot.
  # The checkpoint is unpacked and each stage's index entry becomes the stub file a resume
  # reads (surface/ and volume/stage_NNNN.h5 holding only their "xdmf" attribute).
  local keep out
  keep=$(running_dir "$1") out=$(out_dir "$1")
  [ -f "$keep/checkpoint.h5.xz" ] || return 0
  if holds_run "$out"; then
    [ -f "$out/checkpoint.h5" ] ||
      echo "restore: $out holds a run without a checkpoint; $keep not restored" >&2
    return 0
  fi
  mkdir -p "$out" || return 2
  # the stubs first, the checkpoint last: a folder with a checkpoint is one run.sh resumes
  /usr/bin/python3 - "$keep/index" "$out" <<'EOF' || { echo "restore: cannot write the index stubs into $out" >&2; return 2; }
import os, sys, h5py, numpy
index, out = sys.argv[1:]
for name in sorted(os.listdir(index)):  # <folder>_stage_NNNN.xml: the entry of <folder>/stage_NNNN.h5
    folder, stage = name[:-4].rsplit("_stage_", 1)
    folder = os.path.join(out, *folder.split("+"))
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(index, name), "rb") as f, h5py.File(os.path.join(folder, f"stage_{stage}.h5"), "w") as h:
        h.attrs["xdmf"] = numpy.bytes_(f.read())  # a fixed-length string, as wearsim writes it
EOF
  local t part
  for t in "$keep"/tables/*+*; do # the parts' tables a resume reads back (keep_running.sh)
    [ -f "$t" ] || continue
    part=$(basename "$t" | cut -d+ -f1)
    mkdir -p "$out/parts/$part" && cp "$t" "$out/parts/$part/$(basename "$t" | cut -d+ -f2-)" ||
      { echo "restore: cannot put $t back into $out" >&2; return 2; }
  done
  xz -dc "$keep/checkpoint.h5.xz" > "$out/checkpoint.h5.tmp" && mv "$out/checkpoint.h5.tmp" "$out/checkpoint.h5" ||
    { echo "restore: cannot unpack $keep/checkpoint.h5.xz into $out" >&2; return 2; }
  echo "$keep into $out ($(cat "$keep/kept.txt" 2>/dev/null))"
}
