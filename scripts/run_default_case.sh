#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
mkdir -p build
bash scripts/build.sh
./build/wearsim mesh cases/reference/convex.prm
echo "open output/reference-convex/sample.vtu in ParaView to look at the labelled sample"
