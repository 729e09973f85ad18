#!/usr/bin/env bash
# The real window path (GLFW + ImGui + the orbit camera's loop), under a virtual X server:
# a few frames, a screenshot through --out, exit 0, and a picture that is not blank.
set -euo pipefail
binary=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --window --size 480x360 --frames 2 \
  --out "$out/window.png"
test -s "$out/window.png"
# A blank frame compresses to almost nothing; a real one with the panel does not.
size=$(stat -c %s "$out/window.png")
if ((size < 20000)); then
  echo "window.png is only $size bytes: blank?"
  exit 1
fi
echo "window ok: $size bytes"
