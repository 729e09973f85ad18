#!/bin/sh
# scripts/gpu_check.sh end to end, --short, on Mesa's software EGL device (egl-device, the
# path a GPU takes): a bundle with the short cases' llvmpipe references, the check run from
# it, and its summary read back: the device named, every view of the short cases identical to
# llvmpipe's (it is llvmpipe), issue 10's target rows with numbers and a verdict, the copy
# paths and slices measured.
#
#   tests/gpu_check_test.sh SOURCE_DIR BUILD_DIR
set -u
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tmp=$(mktemp -d /tmp/shadows_gpu_check.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

"$src/scripts/bundle.sh" --build "$build" --out "$tmp/bundle" --short || exit 1
"$tmp/bundle/gpu_check.sh" --short --out "$tmp/out"
status=$?
[ $status = 0 ] || fail "gpu_check.sh exited $status"
summary=$tmp/out/summary.md
[ -f "$summary" ] || { echo "FAIL no summary.md"; exit 1; }
cat "$summary"

grep -q '^# GPU check: llvmpipe' "$summary" || fail "the summary does not name the renderer"
grep -q 'backend egl-device, device 0 (Mesa software)' "$summary" ||
  fail "the summary does not name the EGL device"
# The short cases, every view: the same renderer as the references, so nothing moves at all.
for case in 03_shadow_map_basic 06_dual_texture_8bit 03_shadow_map_basic.narrow_light; do
  f=$tmp/out/views/$case.txt
  [ -f "$f" ] || { fail "no views/$case.txt"; continue; }
  views=$(grep -c '^view ' "$f")
  same=$(grep -c '^view .*: 0 pixels differ by more than 0 levels, largest difference 0$' "$f")
  [ "$views" -ge 4 ] && [ "$views" = "$same" ] || fail "$case: $same of $views views identical"
  grep -q '^FAIL' "$f" && fail "$case: $(grep '^FAIL' "$f" | head -1)"
  grep -q '^exit 0$' "$f" || fail "$case: flavour_views did not exit 0"
  grep -q "^| $case | $views/$views | " "$summary" || fail "$case: not in the summary as $views/$views"
done
# Issue 10's rows measured on this run (cubes is the only preset --short renders), with a verdict.
number='[0-9][0-9]*\.[0-9][0-9]×'
for row in "03 defaults, map cached: frame / unshadowed frame" \
           "03 defaults, map every frame: frame / unshadowed frame" \
           "05 3×3 grid, every tap, cubes: eye pass / unshadowed" \
           "05 3×3 grid, early out, cubes: eye pass / unshadowed" \
           "05 one tap (none), cubes: eye pass / unshadowed"; do
  grep -q "^| $row | $number | $number | ≤ [0-9.]*× | \(\*\*met\*\*\|missed\) |$" "$summary" ||
    fail "no measured row: $row"
done
grep -q '^| read_pixels | ' "$summary" || fail "no copy-path row"
grep -q '^| copy_texture | ' "$summary" || fail "no copy-path row for copy_texture"
grep -q '^| 16 | 2 | [0-9]' "$summary" || fail "no slice row"
for csv in shadow_cost pcf_cost 06_dual_texture_8bit 08_atmospherics; do
  grep -q 'llvmpipe' "$tmp/out/bench/$csv.csv" 2> /dev/null || fail "bench/$csv.csv missing"
done
grep -q 'Mesa software' "$tmp/out/machine.txt" || fail "machine.txt does not list the devices"

[ $failures = 0 ] && echo "gpu_check: ok" && exit 0
exit 1
