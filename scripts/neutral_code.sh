#!/usr/bin/env bash
# What leaving a neutral slider's code out saves (issue 56): for each feature that
# gl/program.hpp's feature() compiles only where its setting does work, one frame at the
# setting's neutral value counted by callgrind (scripts/frame_instructions.sh: map cached,
# instructions per frame, the median of three) with the code left out, as the lessons run it,
# and compiled in (SHADOWS_KEEP_NEUTRAL_CODE=the row's features, the others as they run), and
# what leaving it out saves. The pictures are the same
# byte for byte (tests/test_lesson_variants.cpp, NeutralCode, checks every view of these
# cases). Prints a markdown table; about a minute a row on a 2-core machine.
#
# Usage: scripts/neutral_code.sh [--size WxH] [--lessons L1,L2]
#   (default 800x600, every row; --lessons keeps the rows of those lessons, e.g. after a change
#   to their shaders)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
size=800x600
only=
while [[ $# -gt 0 ]]; do
  case $1 in
    --size) size=$2; shift 2 ;;
    --lessons) only=,$2,; shift 2 ;;
    *) sed -n 11,13p "${BASH_SOURCE[0]}" >&2; exit 2 ;;
  esac
done
# lesson | features | the neutral settings (the test's cases, and some together)
cases=(
  "04_bias_offset|GRADIENT_TERM|bias.mode=gradient bias.factor=0"
  "04_bias_offset|CONSTANT_TERM|bias.mode=gradient bias.units=0"
  "04_bias_offset|GRADIENT_TERM,CONSTANT_TERM|bias.mode=gradient bias.factor=0 bias.units=0"
  "04_bias_offset|NORMAL_OFFSET|bias.mode=normal_offset bias.factor=0"
  "11_omni_cube|NORMAL_OFFSET|bias.normal=0"
  "12_cascades|KEPT_CASCADES|(the default)"
  "12_cascades|KEPT_CASCADES|cascades.update=2"
  "12_cascades|CASCADE_BLEND|cascades.blend=0"
  "12_cascades|NORMAL_OFFSET|bias.normal=0"
  "12_cascades|CASCADE_BLEND,NORMAL_OFFSET|cascades.blend=0 bias.normal=0"
  "13_filterable_maps|BLEEDING_REDUCTION|(the default)"
  "05_pcf_dithered|PCF_KERNEL|pcf.radius=0"
  "05_pcf_dithered|PCF_KERNEL|pcf.mode=grid pcf.taps=9 pcf.early_out=false pcf.radius=0"
  "13_filterable_maps|PCF_KERNEL|filter.method=pcf filter.radius=0"
  "14_soft_shadows|PCF_KERNEL|pcss.mode=fixed pcf.radius=0"
  "14_soft_shadows|PCSS_SEARCH|pcss.light_radius=0"
  "08_atmospherics|AIR_SLICES|air.density=0"
  "02_projective_texture|SPOT_FALLOFF|(the default)"
)
frame() {  # LESSON SETTINGS...: the frame's M instructions
  local lesson=$1
  shift
  local sets=()
  for s in "$@"; do [[ $s == "(the default)" ]] || sets+=(--set "$s"); done
  "$repo/scripts/frame_instructions.sh" "$lesson" --size "$size" "${sets[@]}" |
    sed -n 's/^frame \([0-9.]*\) M instructions.*/\1/p'
}
echo "| lesson | left out at its neutral value | settings | compiled in (M) | left out (M) | saved |"
echo "|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  IFS='|' read -r lesson feature settings <<<"$c"
  [[ -z $only || $only == *,$lesson,* ]] || continue
  if [[ $settings == "(the default)" ]]; then args=("(the default)"); else read -ra args <<<"$settings"; fi
  echo "neutral_code: $lesson $settings" >&2
  kept=$(SHADOWS_KEEP_NEUTRAL_CODE=$feature frame "$lesson" "${args[@]}")
  out=$(SHADOWS_KEEP_NEUTRAL_CODE= frame "$lesson" "${args[@]}")
  python3 -c "import sys; k, o = float(sys.argv[1]), float(sys.argv[2]); \
print(f'| {sys.argv[3]} | {sys.argv[4]} | \`{sys.argv[5]}\` | {k:.2f} | {o:.2f} | {100 * (k - o) / k:.1f} % |')" \
    "$kept" "$out" "$lesson" "${feature//,/, }" "$settings"
done
