#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default test suite (everything but the
# tests labelled "long"; run those with: ctest --test-dir build -L long).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
mkdir -p build
bash scripts/build.sh
ctest --test-dir build -LE long -j "$(nproc)" --output-on-failure --timeout 1500
