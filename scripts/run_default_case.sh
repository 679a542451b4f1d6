#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default case: cases/quick (plain vs convex
# sample in the reference study's set-up at s = 7, coupled DEM-FEM stages), then prints the
# reduction with its 95 % interval, its distance from the full study at s = 7 and the study's
# answer at s = 3, and writes the plots and output/quick/report.md.
#
# usage: bash scripts/run_default_case.sh [--update-readme]
#        --update-readme: also write the README's figures and picture from this run
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  ""|--update-readme) ;;
  *) echo "run_default_case.sh: unknown argument '$1' (only --update-readme)" >&2; exit 2 ;;
esac
bash scripts/install_deps.sh
mkdir -p build
bash scripts/build.sh
bash cases/quick/run.sh "$@"
echo
echo "report: output/quick/report.md; comparison plot: output/quick/compare.png"
echo "plots of each run: output/quick/plain/parts/sample/plots/, output/quick/convex/parts/sample/plots/"
echo "ParaView: output/quick/convex/parts/sample/history.xdmf (sample surface and volume per stage)"
