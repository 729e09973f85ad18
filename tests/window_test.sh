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
# A window run honours the same output flags as a headless one, all or nothing.
first=$1
xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 1 \
  --out "$out/w.png" --report "$out/w.json" --error-out "$out/w_error.png"
test -s "$out/w.json" && test -s "$out/w_error.png" && grep -q '"false_shadow_pct"' "$out/w.json"
if xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 1 \
  --out "$out/f.png" --report /dev/full; then
  echo "a window run whose report cannot be written exited 0"
  exit 1
fi
test ! -e "$out/f.png" || { echo "the window's picture stayed without its report"; exit 1; }
echo "window outputs ok"
# --hide-panel: the same window without the panel, so it costs what headless costs.
xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 1 \
  --hide-panel --out "$out/hidden.png" --report "$out/hidden.json"
# The same window with the panel (w.png above) differs from it only where the panel was.
if cmp -s "$out/w.png" "$out/hidden.png"; then
  echo "--hide-panel: the picture is the same as with the panel"
  exit 1
fi
echo "hidden panel ok"
# Past its first frames the panel is laid from its cached texture, not drawn anew: still
# there at frame 12 (a picture unlike the hidden-panel one, and not blank).
xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 12 \
  --out "$out/cached.png"
xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 12 \
  --hide-panel --out "$out/cached_hidden.png"
if cmp -s "$out/cached.png" "$out/cached_hidden.png"; then
  echo "frame 12: the cached panel was not laid over the frame"
  exit 1
fi
echo "cached panel ok"
# Outputs without --out, or --frames alone, are honoured too: the run stops after its frames
# (a timeout turns "ignored, the window stays open" into a failure) and writes what was asked.
timeout 120 xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 2 \
  --report "$out/only.json" --truth-out "$out/only_truth.png"
test -s "$out/only.json" && test -s "$out/only_truth.png" ||
  { echo "a window run with --report and --truth-out but no --out wrote nothing"; exit 1; }
grep -q '"frames": 2' "$out/only.json" || { echo "the window ignored --frames"; exit 1; }
timeout 120 xvfb-run -a -s "-screen 0 1024x768x24" "$first" --window --size 320x240 --frames 1 \
  --no-truth
echo "outputs without --out ok"
