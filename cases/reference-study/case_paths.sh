# Where a case of the reference study's scripts lives (run.sh, save_state.sh, restore.sh), and
# how its kept run comes back. Sourced, not run.
# A case is the name of a case file in cases/reference-study without .prm (its output folder
# output/reference-study/<name>), or the path of another case file run by the study's engine,
# such as cases/wear-out/convex.prm, whose output folder is the `set Directory` written in the
# file itself and whose kept run is named after that folder.

case_file() { # <case>: its case file
  case "$1" in *.prm) echo "$1" ;; *) echo "cases/reference-study/$1.prm" ;; esac
}

out_dir() { # <case>: its output folder
  case "$1" in
    *.prm) sed -n 's/^[[:space:]]*set[[:space:]]\+Directory[[:space:]]*=[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$1" | tail -n 1 ;;
    *) echo "output/reference-study/$1" ;;
  esac
}

kept_name() { # <case>: the name of its kept run in cases/reference-study/state
  case "$1" in *.prm) basename "$(out_dir "$1")" ;; *) echo "$1" ;; esac
}

restore_kept() { # <case> [for-report]: its kept run (save_state.sh) into its output folder, if
  # that holds none; prints what the kept run holds when it unpacked one, nothing otherwise;
  # fails when it cannot. A kept run without a checkpoint (the reference scheme keeps none)
  # cannot be continued: it is unpacked only for the reports (restore.sh passes for-report),
  # so that run.sh starts such a case afresh instead of overwriting what it unpacked.
  local kept out
  kept="cases/reference-study/state/$(kept_name "$1").tar.xz" out=$(out_dir "$1")
  [ -f "$kept" ] && [ ! -f "$out/checkpoint.h5" ] || return 0
  if [ "${2:-}" = for-report ]; then
    [ ! -f "$out/summary.csv" ] || return 0
  elif ! tar -tJf "$kept" ./checkpoint.h5 > /dev/null 2>&1; then
    return 0
  fi
  mkdir -p "$out"
  tar -C "$out" -xJf "$kept" || { echo "cannot unpack $kept into $out" >&2; return 2; }
  # its log goes back beside the folder, where run.sh appends to it, unless one is there
  if [ -f "$out/run.log" ]; then
    [ -f "$out.log" ] || mv "$out/run.log" "$out.log"
    rm -f "$out/run.log"
  fi
  cat "${kept%.tar.xz}.txt" 2>/dev/null || echo "$kept"
}
