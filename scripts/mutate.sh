#!/usr/bin/env bash
# Mutation check: does the test suite catch deliberate bugs? Each tests/mutations/*.patch is
# one small bug (its first line says which). For each patch, one at a time, this applies it
# to a scratch worktree of the committed HEAD, rebuilds, runs the whole suite through CTest,
# and reports the tests that failed ("caught") or none ("SURVIVED"); then it reverts the
# patch. Your working tree is never touched. Not part of ./test.sh: it rebuilds per patch
# (about a minute each on 2 cores).
#
# Usage: scripts/mutate.sh [PATCH...]        (default: every tests/mutations/*.patch)
# Environment: MUTATE_DIR  scratch directory (default /tmp/shadows-mutate; its build is
#                          kept between runs, so a second run builds only what changed)
#              JOBS        build and test jobs (default 2)
# Exit status: 0 when every patch was caught, 1 otherwise.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scratch=${MUTATE_DIR:-/tmp/shadows-mutate}
jobs=${JOBS:-2}
patches=("$@")
if ((${#patches[@]} == 0)); then patches=("$repo"/tests/mutations/*.patch); fi
for i in "${!patches[@]}"; do patches[i]=$(realpath "${patches[i]}"); done

src=$scratch/src build=$scratch/build log=$scratch/log
mkdir -p "$scratch"
if [[ -e $src ]]; then git -C "$repo" worktree remove --force "$src"; fi
git -C "$repo" worktree prune
git -C "$repo" worktree add --detach "$src" HEAD >/dev/null
# The build directory is reused between runs; a new worktree is the same path, so CMake keeps it.
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null

build_and_test() {  # prints the failed tests, one per line; "(build failed)" if it did not build
  if ! nice -n 15 cmake --build "$build" -j"$jobs" >"$log" 2>&1; then
    echo "(build failed)"
    return
  fi
  nice -n 15 ctest --test-dir "$build" -j"$jobs" >"$log" 2>&1 || true
  sed -n '/The following tests FAILED:/,$p' "$log" | grep -E '^\s+[0-9]+ - ' |
    sed -E 's/^\s+[0-9]+ - //; s/ \(.*$//; s/  #.*$//' || true  # none failed: no lines
}

echo "mutate: baseline (no patch) at $(git -C "$repo" rev-parse --short HEAD)"
baseline=$(build_and_test)
if [[ -n $baseline ]]; then
  echo "mutate: the unpatched suite fails; fix that first:"
  echo "$baseline" | sed 's/^/  /'
  exit 1
fi

caught=0 total=0
summary=()
for patch in "${patches[@]}"; do
  name=$(basename "$patch" .patch)
  total=$((total + 1))
  echo "== $name: $(head -1 "$patch" | sed 's/^Bug: //')"
  if ! git -C "$src" apply "$patch"; then
    echo "   does not apply to HEAD: update the patch"
    summary+=("NOT APPLIED  $name")
    continue
  fi
  failed=$(build_and_test)
  git -C "$src" checkout -- .
  if [[ -n $failed ]]; then
    caught=$((caught + 1))
    echo "$failed" | sed 's/^/   failed: /'
    summary+=("caught       $name ($(echo "$failed" | wc -l) tests)")
  else
    echo "   SURVIVED: no test failed"
    summary+=("SURVIVED     $name")
  fi
done
# Leave the scratch build matching HEAD again.
nice -n 15 cmake --build "$build" -j"$jobs" >"$log" 2>&1 || true

echo
printf '%s\n' "${summary[@]}"
echo "mutate: $caught of $total patches caught"
((caught == total))
