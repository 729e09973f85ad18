#!/usr/bin/env bash
# Instructions per frame, counted by callgrind: deterministic where timings on a shared machine
# are not. One headless run of LESSON (--frames 4, no truth) with a callgrind dump before each
# frame the runner renders and after each of its measured passes (gl/measure.hpp: a pass ends
# in glFinish, so its rasterization is its own); the headless run (run/headless_run.cpp) interleaves the
# lesson's frames with their shadow.off baseline frames, so after the warm-ups the frames
# alternate: baseline, frame, ... llvmpipe rasterizes in the calling thread (LP_NUM_THREADS=0),
# so a pass's shading lands in its own dump. Prints the median of the 3 steady frames and of
# the 3 baselines, and their ratio; then each pass's median, in the order drawn (the first
# includes what the frame did before it), and what the frame spent after its last pass. Needs a build (cmake --build build --target LESSON) and
# valgrind.
#
# Usage: scripts/frame_instructions.sh LESSON [lesson flags...]
#   e.g. scripts/frame_instructions.sh 05_pcf_dithered --size 640x480 --set pcf.mode=grid
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[[ $# -ge 1 ]] || { sed -n 2,14p "${BASH_SOURCE[0]}" >&2; exit 2; }
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
LP_NUM_THREADS=0 valgrind --tool=callgrind --dump-before='*Runner::render(*' \
  --dump-after='*Measure::Pass::~Pass*' --callgrind-out-file="$tmp/cg.out" "$binary" --headless \
  --no-truth --frames 4 "$@" --out /dev/null >/dev/null 2>"$tmp/valgrind.log" ||
  { cat "$tmp/valgrind.log" >&2; exit 1; }
# Rendered frames, in order: 1 the warm-up frame, 2 the warm-up baseline, 3 the first timed
# baseline (it still allocates), then 4 6 8 frames and 5 7 9 baselines; a lesson without
# shadow.off renders no baselines: the warm-up, then the timed frames, the last three counted. A dump before
# Runner::render closes the frame before it (what ran between its last pass and the next frame:
# its tail); one after a pass closes that pass.
python3 - "$tmp" <<'PY'
import glob, re, statistics, sys
dumps = []
for f in glob.glob(sys.argv[1] + '/cg.out.*'):
    text = open(f).read()
    pass_end = re.search(r'^desc: Trigger: --dump-after=.*Measure::Pass::~Pass', text, re.M)
    dumps.append((int(f.rsplit('.', 1)[1]), bool(pass_end),
                  int(re.search(r'^summary: (\d+)', text, re.M).group(1))))
frames, current = [], None  # each frame: [passes..., tail]
for _, pass_end, ir in sorted(dumps):
    if pass_end:
        if current is not None: current[0].append(ir)
    else:
        if current is not None:
            current[1] = ir
            frames.append(current)
        current = [[], 0]
def total(f): return sum(f[0]) + f[1]
if len(frames) in (4, 5):  # a lesson without shadow.off (01, 02): no baselines between them
    lit = frames[-3:]
    frame = statistics.median(map(total, lit))
    print(f"frame {frame / 1e6:.2f} M instructions (no shadow.off frame: the lesson has none)")
    base = None
elif len(frames) < 9:
    sys.exit(f'frame_instructions: {len(frames)} frames dumped, 9 expected')
else:
    lit, base = [frames[i] for i in (3, 5, 7)], [frames[i] for i in (4, 6, 8)]
    frame, baseline = statistics.median(map(total, lit)), statistics.median(map(total, base))
    print(f"frame {frame / 1e6:.2f} M instructions, shadow.off frame {baseline / 1e6:.2f} M, "
          f"ratio {frame / baseline:.3f}")
def passes(fs):
    if len({len(f[0]) for f in fs}) != 1: return 'passes differ between frames'
    cols = [statistics.median(f[0][k] for f in fs) / 1e6 for k in range(len(fs[0][0]))]
    tail = statistics.median(f[1] for f in fs) / 1e6
    return ' + '.join(f'{c:.2f}' for c in cols) + f' M, {tail:.2f} M after them'
print(f"passes in the order drawn: frame {passes(lit)}" +
      (f"; shadow.off frame {passes(base)}" if base else ""))
PY
