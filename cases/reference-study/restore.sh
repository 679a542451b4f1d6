#!/usr/bin/env bash
# Unpacks kept runs (save_state.sh) into their output folders, as run.sh does before it
# continues a run, so that the reports (docs/results/reference_study_report.py, which reads
# output/reference-study, and holder_cases_report.py, which reads the wear-out and stress
# cases' folders) see the finished runs on a machine that did not make them.
# A folder that already holds a run is left as it is.
#
# usage: bash cases/reference-study/restore.sh [case ...]
#        case: as for run.sh (case_paths.sh); default: every kept run that has a case file here
#              or in cases/wear-out and cases/stress
set -euo pipefail
cd "$(dirname "$0")/../.."
source cases/reference-study/case_paths.sh
cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
  for kept in cases/reference-study/state/*.tar.xz; do
    c=$(basename "$kept" .tar.xz)
    [ -f "cases/reference-study/$c.prm" ] && cases+=("$c")
  done
  for f in cases/wear-out/*.prm cases/stress/*.prm; do
    [ -f "cases/reference-study/state/$(kept_name "$f").tar.xz" ] && cases+=("$f")
  done
fi
for c in "${cases[@]}"; do
  [ -f "$(case_file "$c")" ] || { echo "restore.sh: no case file $(case_file "$c")" >&2; exit 2; }
  [ -f "cases/reference-study/state/$(kept_name "$c").tar.xz" ] ||
    { echo "restore.sh: $c has no kept run (cases/reference-study/state/$(kept_name "$c").tar.xz)" >&2; exit 2; }
  restored=$(restore_kept "$c" for-report) || { echo "restore.sh: $c not restored" >&2; exit 2; }
  echo "restore.sh: $c: ${restored:-$(out_dir "$c") already holds a run, left as it is}"
done
