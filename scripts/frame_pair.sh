#!/usr/bin/env bash
# Two lessons' frames timed against each other: ROUNDS interleaved rounds (A, B, A, B, ...),
# each a headless run of FRAMES frames whose report gives its median frame_ms (and the same
# frame with shadow.off, baseline_frame_ms). Prints per round, then the medians and B's
# median over A's. A timing, for benchmarks and READMEs, never a test: quote the load average
# it prints.
#
# Usage: scripts/frame_pair.sh A B [ROUNDS] [lesson flags...]
#   e.g. scripts/frame_pair.sh 03_shadow_map_basic 04_bias_offset 15 --set scene=cubes
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[[ $# -ge 2 ]] || { sed -n 2,9p "${BASH_SOURCE[0]}" >&2; exit 2; }
a=$1 b=$2
shift 2
rounds=15
if [[ $# -gt 0 && $1 =~ ^[0-9]+$ ]]; then rounds=$1; shift; fi
for lesson in "$a" "$b"; do
  [[ -x $repo/build/$lesson ]] || { echo "frame_pair: $repo/build/$lesson not built" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "frame_pair: $a against $b, $rounds rounds, $* (load average $(cut -d' ' -f1-3 /proc/loadavg))"
for ((r = 1; r <= rounds; ++r)); do
  for lesson in "$a" "$b"; do
    "$repo/build/$lesson" --headless --no-truth --size 640x480 --frames 30 "$@" --out /dev/null \
      --report "$tmp/$lesson.json" >/dev/null
    python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["frame_ms"], r["baseline_frame_ms"])' \
      "$tmp/$lesson.json" >>"$tmp/$lesson.times"
  done
  echo "round $r: $a $(tail -1 "$tmp/$a.times" | cut -d' ' -f1) ms, $b $(tail -1 "$tmp/$b.times" | cut -d' ' -f1) ms"
done
python3 - "$tmp/$a.times" "$tmp/$b.times" "$a" "$b" <<'PY'
import statistics, sys
ta = [list(map(float, l.split())) for l in open(sys.argv[1])]
tb = [list(map(float, l.split())) for l in open(sys.argv[2])]
med = lambda rows, k: statistics.median(r[k] for r in rows)
a, b = sys.argv[3], sys.argv[4]
print(f"median frame: {a} {med(ta, 0):.3f} ms, {b} {med(tb, 0):.3f} ms: {b} / {a} = {med(tb, 0) / med(ta, 0):.3f}x")
print(f"median baseline (shadow.off): {a} {med(ta, 1):.3f} ms, {b} {med(tb, 1):.3f} ms: "
      f"{med(tb, 1) / med(ta, 1):.3f}x (the same frame: how far apart the two runs are anyway)")
ratios = sorted(y[0] / x[0] for x, y in zip(ta, tb))
print(f"per round {b} / {a}: median {statistics.median(ratios):.3f}x, range {ratios[0]:.3f}-{ratios[-1]:.3f}x")
PY
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
