#!/usr/bin/env bash
# Installs what the build needs (Debian packages), then configures and builds into build/
# (everything, or with --lessons only the lesson programs, or --lessons NAME... those). Called
# by run.sh and test.sh so both doors set up the same way. The lessons' door is quiet: make's
# lines go to build/setup.log, and a real rebuild shows one progress line.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(build-essential cmake pkg-config python3-glad
  libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libegl-mesa0 libimgui-dev libstb-dev
  libembree-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev xvfb xauth gnuplot-nox nodejs)
# The pages and their browser tests (setup_pages.sh) for the full set-up only, and before
# configuring: tests/CMakeLists.txt registers the web tests where em++ is found. The lessons'
# door (run.sh, --lessons) does not need them.
[[ ${1:-} == --lessons ]] || packages+=(emscripten chromium)
# Debian packs npm apart from node; some nodejs packages (NodeSource's) bring their own.
command -v npm >/dev/null || packages+=(npm)
source scripts/packages.sh
ensure_packages setup "${packages[@]}"

# The web truth's tracer (three-mesh-bvh), which its agreement test runs under node; a lesson
# run natively does not need it.
[[ ${1:-} == --lessons ]] || scripts/setup_web.sh

jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
if [[ ${1:-} == --lessons ]]; then
  shift
  targets=()
  if (($#)); then
    for name in "$@"; do targets+=(--target "$name"); done
  else
    for dir in [0-9][0-9]_*/; do [[ -f $dir/main.cpp ]] && targets+=(--target "${dir%/}"); done
  fi
  # make's own lines into the log; one line, rewritten in place, while something is built.
  log=build/setup.log
  if ! cmake --build build -j"$jobs" "${targets[@]}" 2>&1 | tee "$log" |
    awk -v names="${*:-the lessons}" '
      /^\[ *[0-9]+%\] (Building|Linking)/ {
        printf "\rsetup: building %s into build/ with '"$jobs"' jobs: %s", names, substr($0, 2, 4)
        fflush(); shown = 1 }
      END { if (shown) print "" }'; then
    echo "setup: the build failed; its last lines (all of them in $log):"
    tail -n 25 "$log"
    exit 1
  fi
else
  echo "setup: building into build/ with $jobs jobs"
  cmake --build build -j"$jobs"
  # The web pages and what their browser tests need (tests/CMakeLists.txt, WebPage.*).
  scripts/setup_pages.sh
fi
