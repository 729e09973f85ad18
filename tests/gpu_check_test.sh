#!/bin/sh
# scripts/gpu_check.sh end to end, --short, on Mesa's software EGL device (egl-device, the
# path a GPU takes): a bundle with the short cases' llvmpipe references, the check run from
# it, and its summary read back: the device named, every view of the short cases identical to
# llvmpipe's (it is llvmpipe), issue 10's target rows with numbers and a verdict, the copy
# paths and slices measured, and a last line that says it passed. Then (issue 31) the check
# from a bundle made --no-references: it says once that there is nothing to compare with, no
# case FAILs for it, and the summary says which cases were not compared; and from a copy of
# the first bundle with two references broken (one missing, one another view's picture): it
# names both cases and exits 1.
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
"$tmp/bundle/gpu_check.sh" --short --out "$tmp/out" > "$tmp/check.txt" 2>&1
status=$?
cat "$tmp/check.txt"
[ $status = 0 ] || fail "gpu_check.sh exited $status"
tail -1 "$tmp/check.txt" | grep -q '^gpu_check: passed, no failures; ' ||
  fail "the last line is not the verdict: $(tail -1 "$tmp/check.txt")"
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

short_cases="03_shadow_map_basic 06_dual_texture_8bit 03_shadow_map_basic.narrow_light"
# A bundle without references: nothing to compare with is said once, and is no FAIL.
"$src/scripts/bundle.sh" --build "$build" --out "$tmp/bare" --no-references > /dev/null || exit 1
"$tmp/bare/gpu_check.sh" --short --out "$tmp/bare_out" > "$tmp/bare.txt" 2>&1
status=$?
[ $status = 0 ] || fail "without references: gpu_check.sh exited $status"
said=$(grep -c 'no references' "$tmp/bare.txt")
[ "$said" = 1 ] || fail "without references: 'no references' said $said times, not once"
for case in $short_cases; do
  f=$tmp/bare_out/views/$case.txt
  grep -q '^FAIL' "$f" && fail "without references, $case: $(grep '^FAIL' "$f" | head -1)"
  grep -q "^| $case | not compared" "$tmp/bare_out/summary.md" ||
    fail "without references: the summary does not say $case was not compared"
done
tail -1 "$tmp/bare.txt" | grep -q '^gpu_check: passed, no failures; 3 of 3 cases not compared' ||
  fail "without references, the last line: $(tail -1 "$tmp/bare.txt")"

# Broken references: a missing picture and a wrong one are failures, and the exit says so.
cp -a "$tmp/bundle" "$tmp/broken"
ref=$tmp/broken/share/shadows/reference
rm "$ref/03_shadow_map_basic.narrow_light/shaded.png"
for other in "$ref"/06_dual_texture_8bit/*.png; do
  [ "${other##*/}" = shaded.png ] || break
done
cp "$other" "$ref/06_dual_texture_8bit/shaded.png"
"$tmp/broken/gpu_check.sh" --short --out "$tmp/broken_out" > "$tmp/broken.txt" 2>&1
status=$?
[ $status = 1 ] || fail "with two broken references: gpu_check.sh exited $status, not 1"
for case in 06_dual_texture_8bit 03_shadow_map_basic.narrow_light; do
  grep -q "^FAIL views $case: " "$tmp/broken.txt" || fail "with broken references: $case not named"
done
tail -1 "$tmp/broken.txt" | grep -q '^gpu_check: FAILED, [0-9][0-9]* failures (views: 06_dual_texture_8bit 03_shadow_map_basic.narrow_light; ' ||
  fail "with broken references, the last line: $(tail -1 "$tmp/broken.txt")"
grep -q '^\*\*Result: [0-9][0-9]* failures\*\*' "$tmp/broken_out/summary.md" ||
  fail "with broken references: the summary has no result line with the failures"

[ $failures = 0 ] && echo "gpu_check: ok" && exit 0
exit 1
