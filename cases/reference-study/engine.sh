#!/usr/bin/env bash
# The study's engine: every run of the reference study (and its calibration) is made by one
# engine version, the commit named in cases/reference-study/ENGINE, so that the report can put
# them side by side (docs/results/reference_study_report.py refuses mixed versions). The code
# on main moves on; this builds that commit's `wearsim` once per machine, in a git worktree
# beside the checkout, and prints the binary's path on standard output.
#
# usage: bash cases/reference-study/engine.sh [ENGINE file]  # prints the path, builds if needed
#        ENGINE file: the commit of another study (default cases/reference-study/ENGINE; the
#        wear-out study has its own, cases/wear-out/ENGINE)
#        STUDY_ENGINE_DIR=<dir> (default /work/study-engine-<commit>, or
#        ../study-engine-<commit> from the root)
#
# A binary that already reports the engine's version (`wearsim --version`), e.g. build/wearsim
# made from a clean checkout of that very commit, is copied instead of building again: the
# version is `git describe --dirty` of the tree it was built from, so it names the sources.
set -euo pipefail
cd "$(dirname "$0")/../.."
engine_file=${1:-cases/reference-study/ENGINE}
commit=$(tr -d ' \n' < "$engine_file")
[[ "$commit" =~ ^[0-9a-f]{12}$ ]] ||
  { echo "engine.sh: $engine_file must hold a 12-digit commit, not '$commit'" >&2; exit 2; }
dir=${STUDY_ENGINE_DIR:-$( [ -d /work ] && echo "/work/study-engine-$commit" || echo "$(pwd)/../study-engine-$commit")}
bin="$dir/bin/wearsim"
reports() { [ -x "$1" ] && [ "$("$1" --version 2>/dev/null)" = "wearsim $commit" ]; }
if reports "$bin"; then
  echo "$bin"
  exit 0
fi
mkdir -p "$dir/bin"
if reports build/wearsim; then
  echo "engine.sh: build/wearsim is engine $commit; copied to $bin" >&2
  cp build/wearsim "$bin.tmp" && mv "$bin.tmp" "$bin"
  echo "$bin"
  exit 0
fi
git cat-file -e "$commit^{commit}" 2>/dev/null ||
  { echo "engine.sh: commit $commit is not in this repository (a shallow clone? git fetch --unshallow)" >&2; exit 2; }
src="$dir/src"
if [ ! -d "$src" ]; then
  echo "engine.sh: checking out engine $commit in $src" >&2
  git worktree add --detach "$src" "$commit" >&2
fi
echo "engine.sh: building engine $commit in $src/build (about 25 min on 2 cores)" >&2
cmake -S "$src" -B "$src/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
nice -n "${NICE:-0}" cmake --build "$src/build" --target wearsim -j "$(nproc)" >&2
reports "$src/build/wearsim" ||
  { echo "engine.sh: the build reports '$("$src/build/wearsim" --version)', not engine $commit" >&2; exit 1; }
cp "$src/build/wearsim" "$bin.tmp" && mv "$bin.tmp" "$bin"
echo "$bin"
