#!/usr/bin/env bash
# Instructions per frame, counted by callgrind: deterministic where timings on a shared machine
# are not. One headless run of LESSON (--frames 4, no truth) with a callgrind dump before each
# frame the runner renders; common/run/outputs.cpp interleaves the lesson's frames with their
# shadow.off baseline frames, so after the warm-ups the dumps alternate: baseline, frame, ...
# llvmpipe rasterizes in the calling thread (LP_NUM_THREADS=0), so a frame's shading lands
# in its own dump. Prints the median of the 3 steady frames and of the 3 baselines, and their
# ratio. Needs a build (cmake --build build --target LESSON) and valgrind.
#
# Usage: scripts/frame_instructions.sh LESSON [lesson flags...]
#   e.g. scripts/frame_instructions.sh 05_pcf_dithered --size 640x480 --set pcf.mode=grid
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[[ $# -ge 1 ]] || { sed -n 2,12p "${BASH_SOURCE[0]}" >&2; exit 2; }
lesson=$1
shift
binary=$repo/build/$lesson
[[ -x $binary ]] || { echo "frame_instructions: $binary not built" >&2; exit 2; }
command -v valgrind >/dev/null || {
  echo "frame_instructions: needs valgrind (apt-get install valgrind)" >&2
  exit 2
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
LP_NUM_THREADS=0 valgrind --tool=callgrind --dump-before='*Runner::renderInto*' \
  --callgrind-out-file="$tmp/cg.out" "$binary" --headless --no-truth --frames 4 "$@" \
  --out /dev/null >/dev/null 2>"$tmp/valgrind.log" || { cat "$tmp/valgrind.log" >&2; exit 1; }
# Dumps: 1 start-up, 2 the warm-up frame, 3 the warm-up baseline, 4 the first timed baseline
# (it still allocates), then 5 7 9 frames and 6 8 10 baselines.
ir() { awk '/^summary:/ {print $2}' "$tmp/cg.out.$1"; }
python3 - "$(ir 5)" "$(ir 7)" "$(ir 9)" "$(ir 6)" "$(ir 8)" "$(ir 10)" <<'PY'
import statistics, sys
v = [int(x) for x in sys.argv[1:]]
frame, base = statistics.median(v[:3]), statistics.median(v[3:])
print(f"frame {frame / 1e6:.2f} M instructions, shadow.off frame {base / 1e6:.2f} M, "
      f"ratio {frame / base:.3f}")
PY
