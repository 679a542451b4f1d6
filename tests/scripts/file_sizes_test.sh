#!/bin/bash
# No file of the repository is over 1 MB (1,048,576 bytes) but those allowed: every file git
# tracks and every untracked file it does not ignore (about to be added) is checked, so that
# run outputs and archives stay out of the tree and its history. Allowed: a test's data file
# (tests/<module>/data/) named in tests/data-files.md or in the README of its data folder,
# which say why it is kept at that size. A running run's kept checkpoint (cases/<case>/running/,
# cases/reference-study/keep_running.sh) is held to the 1 MB of every file: it is kept without
# its particle bed.
# Each file over its limit is printed with its size and what to do; the test fails then, and
# when git or a git checkout is missing (it cannot list the files without them).
#
# usage: bash tests/scripts/file_sizes_test.sh [source dir]   (default: this checkout)
set -uo pipefail
root=$(cd "${1:-$(dirname "$0")/../..}" && pwd)
limit=1048576
fail() { echo "file_sizes_test: $*" >&2; exit 1; }

command -v git > /dev/null ||
  fail "git is not available: the check lists the files git tracks and would add (git ls-files); install git"
top=$(git -C "$root" rev-parse --show-toplevel 2>&1) ||
  fail "$root is not a git checkout ($top); the check lists the files git tracks, run it in a clone"
[ "$(cd "$top" && pwd -P)" = "$(cd "$root" && pwd -P)" ] ||
  fail "$root is not the top of a git checkout (that is $top); run the check on the checkout itself"

named_in_data_docs() { # <path under tests/*/data/>: whether its data docs name the file
  local name
  name=$(basename "$1")
  grep -qF "$name" "$root/tests/data-files.md" 2>/dev/null ||
    grep -qF "$name" "$(dirname "$root/$1")/README.md" 2>/dev/null
}

advice() { # <path>: what to do about a file over its limit
  case "$1" in
    tests/*/data/*)
      echo "a test's data file: name it in tests/data-files.md with the test that reads it and why it cannot be smaller" ;;
    cases/*/running/*)
      echo "a kept checkpoint over 1 MB: keep_running.sh keeps it without its bed; a part's mesh this large needs a coarser case, or the run finished before the session ends" ;;
    *)
      echo "keep it out of the tree: run outputs belong in output/ (ignored); a finished run is kept as its summary (docs/results/run_summary.py, a few hundred kB), an unfinished one by cases/reference-study/keep_running.sh" ;;
  esac
}

listed() { # every file git tracks and every untracked one it does not ignore, "<size>\t<path>\0"
  # (one stat for all; a tracked file deleted in the work tree is left out)
  { git -C "$root" ls-files -z; git -C "$root" ls-files -z --others --exclude-standard; } |
    (cd "$root" && xargs -0 -r stat --printf '%s\t%n\0' 2> /dev/null)
}

n=0 over=0
while IFS=$'\t' read -r -d '' size f; do
  n=$((n + 1))
  [ "$size" -gt "$limit" ] || continue
  case "$f" in
    tests/*/data/*) named_in_data_docs "$f" && continue ;;
  esac
  over=$((over + 1))
  printf '%s: %d bytes (%s MB): %s\n' "$f" "$size" "$(awk -v s="$size" 'BEGIN { printf "%.2f", s / 1048576 }')" \
    "$(advice "$f")"
done < <(listed)
[ "$n" -gt 0 ] || fail "git lists no file in $root"
[ "$over" -eq 0 ] || fail "$over of $n files over 1 MB (1,048,576 bytes) outside the allowed ones (tests/scripts/file_sizes_test.sh)"
echo "file_sizes_test: passed: $n files, none over 1 MB outside the allowed ones"
