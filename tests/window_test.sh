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
# The panel is a column right of the picture, never over it: the window with the panel (w.png
# above) is the 320x240 picture plus the column, its picture byte for byte the hidden-panel
# one, and the column holds the panel (many colours, not a blank strip).
python3 - "$out/w.png" "$out/hidden.png" "$(dirname "$0")" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from png_read import read_png
w, h, shown = read_png(sys.argv[1])
fw, fh, hidden = read_png(sys.argv[2])
if (fw, fh) != (320, 240) or h != 240 or w <= fw:
    sys.exit(f"window sizes: {w}x{h} with the panel, {fw}x{fh} without: no column beside 320x240")
covered = sum(shown[y][:4 * fw] != hidden[y] for y in range(h))
if covered:
    sys.exit(f"the panel covers the picture: {covered} of its rows differ from the hidden-panel run")
colours = {shown[y][4 * x:4 * x + 3] for y in range(h) for x in range(fw, w)}
if len(colours) < 10:
    sys.exit(f"the panel's column shows {len(colours)} colours: no panel drawn there")
PY
echo "hidden panel ok, the panel beside the picture"
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
# Without --size a window is 1280x720: a 940x720 picture and the column.
xvfb-run -a -s "-screen 0 1400x900x24" "$first" --window --frames 1 --out "$out/default.png"
python3 - "$out/default.png" "$(dirname "$0")" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from png_read import read_png
w, h, _ = read_png(sys.argv[1])
if (w, h) != (1280, 720):
    sys.exit(f"the default window is {w}x{h}, not 1280x720")
PY
echo "default window ok"
# An exercise keeps the window its size (issue 55, 4): the grader's 640x480 picture in a
# corner, the goal and its sliders above, the verdict beside; the live figures are the
# grader's to the digit.
exercise_lesson=$(dirname "$first")/04_bias_offset
xvfb-run -a -s "-screen 0 1400x900x24" "$exercise_lesson" --window --exercise 1 --frames 2 \
  --out "$out/exercise.png" --report "$out/exercise.json"
"$exercise_lesson" --grade 1 --report "$out/graded.json" >/dev/null || true
python3 - "$out" "$(dirname "$0")" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[2])
from png_read import read_png
w, h, rows = read_png(sys.argv[1] + "/exercise.png")
if (w, h) != (1280, 720):
    sys.exit(f"an exercise's window is {w}x{h}, not 1280x720")
live = json.load(open(sys.argv[1] + "/exercise.json"))
graded = json.load(open(sys.argv[1] + "/graded.json"))
if live["size"] != [640, 480]:
    sys.exit(f"an exercise's picture is {live['size']}, not the grader's 640x480")
if live["exercise"]["measured"] != graded["exercise"]["measured"]:
    sys.exit(f"live {live['exercise']['measured']} against graded {graded['exercise']['measured']}")
# The strip above the picture is the goal's window (dark), not the sky the lesson clears to.
top = [rows[20][x * 4:x * 4 + 3] for x in range(300, 600, 10)]
if sum(sum(p) for p in top) / len(top) > 200:
    sys.exit("nothing drawn above the exercise's picture")
PY
echo "exercise window ok"
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
