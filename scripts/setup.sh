#!/usr/bin/env bash
# Installs what the build needs (Debian packages), then configures and builds into build/
# (everything, or with --lessons only the lesson programs). Called by run.sh and test.sh so
# both doors set up the same way.
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

# The web truth's tracer (three-mesh-bvh), which its agreement test runs under node.
scripts/setup_web.sh

jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
if [[ ${1:-} == --lessons ]]; then
  targets=()
  for dir in [0-9][0-9]_*/; do [[ -f $dir/main.cpp ]] && targets+=(--target "${dir%/}"); done
  echo "setup: building the lessons into build/ with $jobs jobs"
  cmake --build build -j"$jobs" "${targets[@]}"
else
  echo "setup: building into build/ with $jobs jobs"
  cmake --build build -j"$jobs"
  # The web pages and what their browser tests need (tests/CMakeLists.txt, WebPage.*).
  scripts/setup_pages.sh
fi
