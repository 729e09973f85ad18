#!/usr/bin/env bash
# What the panel costs in a window: the same lesson under xvfb with the panel shown and hidden
# (--hide-panel), alternated ROUNDS times, FRAMES frames each; prints each run's median frame
# and the median ratio. Needs a build (./test.sh or cmake --build build) and xvfb-run.
# With COMPARE=drag: the window while the camera turns (--orbit 2, a scripted drag: a lesson's
# preview quality) against the window at rest, both with the panel, at 800x600.
#
# Usage: scripts/window_cost.sh [LESSON] [ROUNDS] [FRAMES] [panel|drag]
#        (default 03_shadow_map_basic 5 80 panel)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
lesson=${1:-03_shadow_map_basic} rounds=${2:-5} frames=${3:-80} compare=${4:-panel}
binary=$repo/build/$lesson
[[ -x $binary ]] || { echo "window_cost: $binary not built" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "window_cost: xvfb-run not installed" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
case $compare in
  panel) modes=(shown hidden) ;;
  drag) modes=(moving resting) ;;
  *) echo "window_cost: expected panel or drag, got '$compare'" >&2; exit 2 ;;
esac
for ((r = 1; r <= rounds; r++)); do
  for mode in "${modes[@]}"; do
    flag=()
    [[ $mode == hidden ]] && flag=(--hide-panel)
    [[ $mode == moving ]] && flag=(--orbit 2)
    # The CPU seconds of the run (every thread, and the X server's), start-up included: on a
    # machine others load, what the frames would take without them, at one core.
    TIMEFORMAT='%U %S'
    { time xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --window --no-truth --frames "$frames" \
      "${flag[@]}" --out "$tmp/$mode.png" --report "$tmp/$mode-$r.json" >/dev/null 2>&1; } \
      2>"$tmp/$mode-$r.cpu"
  done
done
python3 - "$tmp" "$rounds" "$frames" "${modes[@]}" <<'PY'
import json, statistics, sys
tmp, rounds, frames, a, b = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
ms = {m: [json.load(open(f"{tmp}/{m}-{r}.json"))["frame_ms"] for r in range(1, rounds + 1)]
      for m in (a, b)}
for m, v in ms.items():
    median = statistics.median(v)
    print(f"{m:7}: " + " ".join(f"{x:.2f}" for x in v) +
          f"  median {median:.2f} ms ({1000 / median:.1f} fps)")
ratios = [x / y for x, y in zip(ms[a], ms[b])]
print(f"{a} / {b} per round: " + " ".join(f"{x:.2f}" for x in ratios) +
      f"  median {statistics.median(ratios):.2f}x")
for m in (a, b):
    cpu = [1000 * sum(map(float, open(f"{tmp}/{m}-{r}.cpu").read().split())) / (frames + 1)
           for r in range(1, rounds + 1)]
    print(f"{m:7}: CPU per frame, start-up included: " + " ".join(f"{x:.1f}" for x in cpu) +
          f"  median {statistics.median(cpu):.1f} ms")
PY
