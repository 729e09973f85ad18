#!/usr/bin/env bash
# What the panel costs in a window: the same lesson under xvfb with the panel shown and hidden
# (--hide-panel), alternated ROUNDS times, FRAMES frames each; prints each run's median frame
# and the median ratio. Needs a build (./test.sh or cmake --build build) and xvfb-run.
#
# Usage: scripts/window_cost.sh [LESSON] [ROUNDS] [FRAMES]   (default 03_shadow_map_basic 5 80)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
lesson=${1:-03_shadow_map_basic} rounds=${2:-5} frames=${3:-80}
binary=$repo/build/$lesson
[[ -x $binary ]] || { echo "window_cost: $binary not built" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "window_cost: xvfb-run not installed" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for ((r = 1; r <= rounds; r++)); do
  for mode in shown hidden; do
    flag=()
    [[ $mode == hidden ]] && flag=(--hide-panel)
    xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --window --no-truth --frames "$frames" \
      "${flag[@]}" --out "$tmp/$mode.png" --report "$tmp/$mode-$r.json" >/dev/null
  done
done
python3 - "$tmp" "$rounds" <<'PY'
import json, statistics, sys
tmp, rounds = sys.argv[1], int(sys.argv[2])
ms = {m: [json.load(open(f"{tmp}/{m}-{r}.json"))["frame_ms"] for r in range(1, rounds + 1)]
      for m in ("shown", "hidden")}
for m, v in ms.items():
    print(f"panel {m:6}: " + " ".join(f"{x:.2f}" for x in v) + f"  median {statistics.median(v):.2f} ms")
ratios = [s / h for s, h in zip(ms["shown"], ms["hidden"])]
print("shown / hidden per round: " + " ".join(f"{x:.2f}" for x in ratios) +
      f"  median {statistics.median(ratios):.2f}x")
PY
