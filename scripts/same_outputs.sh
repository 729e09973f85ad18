#!/usr/bin/env bash
# Whether a change that should change nothing changed nothing: every lesson's picture and report
# (timings left out) in a set of runs that reach the runner's paths (each view, the cached and
# uncached map, the texel pass, the truth's pictures, an exercise's grade), written to a folder;
# two folders compared.
#   scripts/same_outputs.sh record DIR [BUILD]   # BUILD: build (default)
#   scripts/same_outputs.sh compare DIR_A DIR_B  # exit 1 and the differences when any
# Record before the change and after it, then compare.
set -euo pipefail
cd "$(dirname "$0")/.."

strip_timings() {  # a report without what moves from run to run: times and ratios of times
  python3 -c '
import json, sys
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items()
                if not (k.endswith("_ms") or k in ("shadow_overhead", "renderer", "vendor"))}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
print(json.dumps(clean(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))' "$1"
}

record() {
  local dir=$1 build=${2:-build}
  mkdir -p "$dir"
  local n=0
  run() {  # run NAME LESSON ARGS...: its picture, its stripped report, its stdout's verdict lines
    local name=$1 lesson=$2
    shift 2
    local bin
    bin=$(ls "$build"/"$lesson"_* | head -1)
    "$bin" --headless --size 160x120 --frames 2 --out "$dir/$name.png" --report "$dir/$name.raw.json" \
      "$@" >"$dir/$name.out" 2>"$dir/$name.err" || echo "exit $?" >>"$dir/$name.out"
    sed -i -E "s#$dir/##; s/ +/ /g; s/frame [0-9.]+ ms/frame ms/; s/, [0-9.]+x without shadow//" "$dir/$name.out"
    if [[ -f $dir/$name.raw.json ]]; then
      strip_timings "$dir/$name.raw.json" >"$dir/$name.json"
      rm "$dir/$name.raw.json"
    fi
    n=$((n + 1))
    printf '\r%s: %d runs' "$dir" "$n" >&2
  }
  for l in 01 02 03 04 05 06 07 08 09 10 11 12 13 14 15; do
    run "$l" "$l"
    run "$l.truth" "$l" --set view=truth --truth-out "$dir/$l.truth_out.png" --error-out "$dir/$l.error_out.png"
    run "$l.error" "$l" --set view=error
    run "$l.visibility" "$l" --set view=visibility
    run "$l.notruth" "$l" --no-truth
  done
  for l in 03 04 05 06 07 10; do run "$l.aliasing" "$l" --set view=aliasing; done
  for l in 03 05 13 14; do run "$l.off" "$l" --set shadow.off=1; done
  for l in 05 12; do run "$l.nocache" "$l" --set shadow.cache=0; done
  run 15.light_depth 15 --set view=light_depth
  run 15.hybrid 15 --set lightmap.mode=hybrid
  run 15.map 15 --set lightmap.mode=map
  run 13.esm 13 --set filter.method=esm
  run 10.lispsm 10 --set light.projection=lispsm
  run 08.air 08 --set view=air
  run 11.cube_cross 11 --set view=cube_cross
  run 12.cascades 12 --set view=cascades
  run 14.penumbra 14 --set view=penumbra
  run 03.panel_notiming 03 --panel --no-truth --set view=light_depth
  for l in 03 05 12; do
    local bin
    bin=$(ls "$build"/"$l"_* | head -1)
    "$bin" --grade 1 >"$dir/$l.grade1.out" 2>&1 || echo "exit $?" >>"$dir/$l.grade1.out"
    sed -i -E 's/ +/ /g; s/frame [0-9.]+ ms/frame ms/; s/, [0-9.]+x without shadow//' "$dir/$l.grade1.out"
  done
  echo >&2
}

case ${1:-} in
  record) record "${2:?folder}" "${3:-build}" ;;
  compare)
    a=${2:?folder A} b=${3:?folder B}
    diff -r -q "$a" "$b" >/dev/null && { echo "same: $(ls "$a" | wc -l) files"; exit 0; }
    diff -r "$a" "$b" | head -80
    exit 1
    ;;
  *) sed -n 2,8p "$0" >&2; exit 2 ;;
esac
