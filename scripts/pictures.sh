#!/usr/bin/env bash
# Renders the pictures of the lesson READMEs, headless, by the lessons themselves.
# Each lesson lists them in NN_name/pictures.txt, one per line:
#   file.png  --set name=value ...       (any lesson flags; '#' starts a comment)
# and gets NN_name/pictures/file.png plus NN_name/pictures/numbers.md, a table of the
# error and timing of every picture (the numbers the README quotes). Frame times are of
# static frames: where a lesson caches its shadow map, they leave the map pass out. Lessons
# that report the size of a map step (06, 07) get it too, in world units at the nearest and
# farthest caster. A line with --window is the window itself, picture and panel's column, as a
# student sees it: run under a virtual X server (xvfb-run), with frames enough for the panel to
# show the error and the cost.
# Usage: scripts/pictures.sh [lesson-prefix ...]   (default: every lesson)
#   PICTURES_ONLY="panel.png ..." renders only those, keeping the other rows of numbers.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
size=${PICTURE_SIZE:-480x360}
only=${PICTURES_ONLY:-}
selected=("$@")
for list in [0-9][0-9]_*/pictures.txt; do
  lesson=$(dirname "$list")
  if ((${#selected[@]})); then
    match=0
    for s in "${selected[@]}"; do [[ $lesson == "$s"* ]] && match=1; done
    ((match)) || continue
  fi
  mkdir -p "$lesson/pictures"
  table="$lesson/pictures/numbers.md"
  rows=()
  air=0  # a lesson with a medium (08) reports the air's error too: two more columns
  steps=0  # 06 and 07 report one map step at the casters: two more columns
  while read -r file flags; do
    [[ -z $file || $file == \#* ]] && continue
    if [[ -n $only && " $only " != *" $file "* ]]; then
      kept=$(grep -F "| $file |" "$table" 2>/dev/null || true)
      if [[ -n $kept ]]; then
        rows+=("$kept")
        grep -q 'air rel' "$table" && air=1
        grep -q 'step at nearest' "$table" && steps=1
        continue
      fi
    fi
    report=$(mktemp)
    run=("$build/$lesson" --headless)
    if [[ " $flags " == *" --window "* ]]; then
      run=(xvfb-run -a -s "-screen 0 2560x1600x24" "$build/$lesson")
    fi
    # shellcheck disable=SC2086  # flags are a list of words on purpose
    "${run[@]}" --size "$size" --frames 3 --out "$lesson/pictures/$file" --report "$report" $flags
    num() { grep -o "\"$1\": [-0-9.e+]*" "$report" | head -1 | awk '{printf "%.3g", $2}'; }
    # The truth and error views show a ray-traced picture, not the technique: no frame time.
    frame=$(num frame_ms)
    [[ $flags == *view=truth* || $flags == *view=error* ]] && frame="—"
    row="| $file | \`${flags:-defaults}\` | $(num false_shadow_pct) | $(num false_lit_pct) | $(num vis_mae) | $frame |"
    if grep -q '"air_rel_rmse"' "$report"; then
      air=1
      # null below the truth's floor (air_rel_rmse_note says why): no number, a dash
      rel=$(grep -o '"air_rel_rmse": [-0-9.e+nul]*' "$report" | head -1 |
        awk '{if ($2 == "null") print "—"; else printf "%.3g", 100 * $2}')
      row="$row $rel | $(num air_mae) |"
    fi
    if grep -q '"step_world_at_nearest_caster"' "$report"; then
      steps=1
      row="$row $(num step_world_at_nearest_caster) | $(num step_world_at_farthest_caster) |"
    fi
    rows+=("$row")
    rm -f "$report"
  done <"$list"
  {
    echo "Pictures at $size unless their settings give a \`--size\`, 3 timed frames, by \`scripts/pictures.sh\`."
    echo
    if ((air)); then
      echo "| picture | settings | false shadow % | false lit % | vis_mae | frame ms (map cached) | air rel. RMSE % | air_mae |"
      echo "|---|---|---|---|---|---|---|---|"
    elif ((steps)); then
      echo "| picture | settings | false shadow % | false lit % | vis_mae | frame ms (map cached) | step at nearest caster | step at farthest caster |"
      echo "|---|---|---|---|---|---|---|---|"
    else
      echo "| picture | settings | false shadow % | false lit % | vis_mae | frame ms (map cached) |"
      echo "|---|---|---|---|---|---|"
    fi
    printf '%s\n' "${rows[@]}"
  } >"$table"
  echo "pictures.sh: $lesson: $(grep -c '\.png' "$table") pictures, numbers in $table"
done
