#!/usr/bin/env bash
# ./run.sh [lesson] [flags]: set up, build, then run a lesson (default 01, the first) in a window;
# without a display, render it (or, with no argument at all, every lesson) headless into
# out/<lesson>.png and out/<lesson>.json.
set -euo pipefail
cd "$(dirname "$0")"
# ./run.sh web [port]: build the lessons' web pages (build/web/site/) and serve them locally.
if [[ ${1:-} == web ]]; then
  scripts/setup_pages.sh
  exec node web/serve.mjs build/web/site "${2:-8024}"
fi
# The lessons, from their sources (nothing need be built to name one): ./run.sh 3 is 03.
lessons=()
for dir in [0-9][0-9]_*/; do
  [[ -f $dir/main.cpp ]] && lessons+=("${dir%/}")
done
lesson=01_projected_planar
named=0
if [[ $# -gt 0 && $1 != -* ]]; then
  named=1
  asked=$1
  [[ $asked =~ ^[0-9]$ ]] && asked=0$asked
  for l in "${lessons[@]}"; do [[ $l == "$asked"* ]] && lesson=$l && break; done
  [[ $lesson == "$asked"* ]] || { echo "run.sh: no lesson '$1'; lessons: ${lessons[*]}"; exit 2; }
  shift
fi
# Only what runs: the one lesson (every lesson when a display-less run renders them all). The
# tests and the benchmark are test.sh's business. On a built tree this is quiet and quick.
if [[ -z ${DISPLAY:-} ]] && ((named == 0 && $# == 0)); then
  scripts/setup.sh --lessons
else
  scripts/setup.sh --lessons "$lesson"
fi

if [[ -n ${DISPLAY:-} ]]; then
  # The lesson itself falls back to headless if this DISPLAY leads nowhere.
  exec "build/$lesson" "$@"
fi
mkdir -p out
# Nothing asked for: every lesson. A lesson or flags asked for: that lesson (default 01).
if ((named == 0 && $# == 0)); then
  echo "run.sh: no display, rendering every lesson headless into out/"
  selected=("${lessons[@]}")
else
  echo "run.sh: no display, rendering $lesson headless into out/"
  selected=("$lesson")
fi
for l in "${selected[@]}"; do
  "build/$l" --headless --out "out/$l.png" --report "out/$l.json" "$@"
done
