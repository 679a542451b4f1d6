# Sourced by the report tests (reference_study_report_test.sh, holder_cases_report_test.sh):
# the reports read run summaries only, so each stand-in run folder is summarised first.
# Needs the caller's fail() and $summary (docs/results/run_summary.py).

summarise_stand_ins() { # <runs>: each run folder in <runs> summarised afresh into <runs>.summaries
  local d
  rm -rf "$1.summaries"
  mkdir -p "$1.summaries"
  for d in "$1"/*/; do
    [ -f "$d/summary.csv" ] || continue
    /usr/bin/python3 "$summary" "$d" "$1.summaries/$(basename "$d")" > /dev/null ||
      fail "run_summary.py refused the stand-in $d"
  done
}
