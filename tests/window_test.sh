#!/usr/bin/env bash
# The real window path (GLFW + ImGui + the orbit camera's loop) of every lesson given,
# under a virtual X server: a few frames, a screenshot through --out, exit 0 (no GL error),
# and a picture that is not blank.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for binary in "$@"; do
  name=$(basename "$binary")
  xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --window --size 480x360 --frames 2 \
    --out "$out/$name.png"
  test -s "$out/$name.png"
  # A blank frame compresses to almost nothing; a real one with the panel does not.
  size=$(stat -c %s "$out/$name.png")
  if ((size < 20000)); then
    echo "$name: window.png is only $size bytes: blank?"
    exit 1
  fi
  echo "$name: window ok, $size bytes"
done
