#!/usr/bin/env bash
# The floor of issue 56: each lesson's default frame (map cached) counted by callgrind
# (scripts/frame_instructions.sh) as it runs, and with its shaders' variants replaced by copies
# stripped by hand of every line its default settings leave doing nothing
# (bench/floor/LESSON/, read through SHADOWS_SHADER_FLOOR; common/gl/program.cpp). What the
# lesson pays over the floor is code a neutral value left in. Each row also checks that the
# stripped frame is the same picture byte for byte, and that every stripped file was used (one
# whose variant changed since it was stripped is stale: strip it again). Prints a markdown
# table; about 80 s a lesson on a 2-core machine.
#
# Usage: scripts/neutral_floor.sh [--size WxH] [--lessons L1,L2]
#        scripts/neutral_floor.sh --dump LESSON DIR   (the default frame's variants, to strip)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
size=800x600
only=
usage() { sed -n 11,12p "${BASH_SOURCE[0]}" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --size) size=$2; shift 2 ;;
    --lessons) only=,$2,; shift 2 ;;
    --dump)
      [[ $# -eq 3 ]] || usage
      mkdir -p "$3"
      SHADOWS_SHADER_DUMP=$3 "$repo/build/$2" --headless --no-truth --size "$size" \
        --out /dev/null >/dev/null
      ls "$3"
      exit 0 ;;
    *) usage ;;
  esac
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
count() {  # FLOOR_DIR LESSON: the frame's instructions in millions, frame_instructions' first
  SHADOWS_SHADER_FLOOR=$1 "$repo/scripts/frame_instructions.sh" "$2" --size "$size" |
    sed -n 's/^frame \([0-9.]*\) M.*/\1/p'
}
echo "| lesson | stripped by hand | frame (M) | floor (M) | over the floor |"
echo "|---|---|---|---|---|"
for dir in "$repo"/bench/floor/[0-9][0-9]_*/; do
  lesson=$(basename "$dir")
  [[ -z $only || $only == *",$lesson,"* ]] || continue
  binary=$repo/build/$lesson
  [[ -x $binary ]] || { echo "neutral_floor: $binary not built" >&2; exit 2; }
  # The same picture, and every stripped file read.
  "$binary" --headless --no-truth --size "$size" --out "$tmp/as_run.png" >/dev/null
  SHADOWS_SHADER_FLOOR=$dir "$binary" --headless --no-truth --size "$size" \
    --out "$tmp/floor.png" >/dev/null 2>"$tmp/floor.log"
  if ! cmp -s "$tmp/as_run.png" "$tmp/floor.png"; then
    echo "neutral_floor: $lesson: the stripped shaders draw another picture" >&2
    exit 1
  fi
  for file in "$dir"*.vert "$dir"*.frag "$dir"*.geom; do
    [[ -e $file ]] || continue
    grep -q "shader floor: $(basename "$file")" "$tmp/floor.log" || {
      echo "neutral_floor: $lesson: $(basename "$file") is stale (no variant hashes to it):" \
        "strip the new one (--dump)" >&2
      exit 1
    }
  done
  frame=$(count "" "$lesson") && floor=$(count "$dir" "$lesson") && [[ -n $frame && -n $floor ]] ||
    { echo "neutral_floor: $lesson: frame_instructions.sh could not count it" >&2; exit 1; }
  what=$(sed -n '1p' "$dir/STRIPPED.md")
  awk -v l="$lesson" -v w="$what" -v f="$frame" -v g="$floor" \
    'BEGIN { p = 100 * (f - g) / g; if (p > -0.05 && p < 0.05) p = 0  # no "-0.0"
             printf "| %s | %s | %.2f | %.2f | %.1f %% |\n", l, w, f, g, p }'
done
