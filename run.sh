#!/usr/bin/env bash
# ./run.sh [lesson] [flags]: set up, build, then run a lesson (default 03) in a window;
# without a display, render every lesson headless into out/<lesson>.png.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh

lessons=()
for dir in [0-9][0-9]_*/; do
  [[ -x build/${dir%/} ]] && lessons+=("${dir%/}")
done
lesson=03_shadow_map_basic
if [[ $# -gt 0 && $1 != -* ]]; then
  for l in "${lessons[@]}"; do [[ $l == "$1"* ]] && lesson=$l && break; done
  [[ $lesson == "$1"* ]] || { echo "run.sh: no lesson '$1'; lessons: ${lessons[*]}"; exit 2; }
  shift
fi

if [[ -n ${DISPLAY:-} ]]; then
  exec "build/$lesson" "$@"
fi
echo "run.sh: no display, rendering every lesson headless into out/"
mkdir -p out
for l in "${lessons[@]}"; do
  "build/$l" --headless --out "out/$l.png" --report "out/$l.json" "$@"
done
