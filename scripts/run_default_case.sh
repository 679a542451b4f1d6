#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default case: cases/quick (plain vs convex
# sample, coupled DEM-FEM stages at s = 4 in a 30-degree sector) over three insertion seeds
# per sample, then prints the comparison with 95 % intervals and writes the plots and
# output/quick/report.md.
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
bash cases/quick/ensemble.sh "$@"
echo
echo "report: output/quick/report.md; comparison plot: output/quick/compare.png"
echo "plots of one pair: output/quick/plain-1/plots/, output/quick/convex-1/plots/"
echo "ParaView: output/quick/convex-1/history.xdmf (sample surface and volume per stage)"
