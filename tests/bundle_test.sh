#!/bin/sh
# The bundle (scripts/bundle.sh) is relocatable: at most 60 MiB; with LD_LIBRARY_PATH scrubbed,
# ldd finds every library its programs and libraries need inside it or on the allowlist
# (glibc, GL/EGL); copied to a fresh folder with the source and build trees hidden (a private
# mount namespace with empty folders over them), every lesson renders headless (EGL) with its
# truth; and it reads its own shaders, not the source tree's (a broken copy makes it fail).
# Its --out folder is replaced whole, so bundle.sh refuses, exit 2 in one line and touching
# nothing, any folder it did not make (issue 31): an empty path, /, a file, a link, a folder
# of the user's, and a bundle of its own into which the user put a file; it replaces a bundle
# of its own (the marker .shadows_bundle says so).
#
#   tests/bundle_test.sh SOURCE_DIR BUILD_DIR
set -u
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tmp=$(cd "$(mktemp -d /tmp/shadows_bundle.XXXXXX)" && pwd -P)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# refuses WHAT BUILD_DIR OUT_DIR: bundle.sh --out OUT_DIR exits 2 with one line.
refuses() {
  what=$1
  shift
  "$src/scripts/bundle.sh" --build "$1" --out "$2" --no-references > "$tmp/refused.txt" 2>&1
  status=$?
  lines=$(grep -c . "$tmp/refused.txt")
  if [ $status != 2 ] || [ "$lines" != 1 ]; then
    fail "bundle.sh --out '$2' ($what): exit $status and $lines lines, not exit 2 and one line:"
    head -5 "$tmp/refused.txt"
  fi
}
# With a build folder holding no programs: the old script stopped there before writing into
# /bin, /lib, /share (--out '') or deleting /; the refusal comes before it looks at the build.
mkdir -p "$tmp/no_build"
refuses "an empty path" "$tmp/no_build" ''
refuses "the root folder" "$tmp/no_build" /
refuses "the root folder, spelt //" "$tmp/no_build" //
echo "a file" > "$tmp/a_file"
refuses "a file" "$tmp/no_build" "$tmp/a_file"
grep -q '^a file$' "$tmp/a_file" || fail "bundle.sh --out FILE changed the file"
# A folder of the user's, with the real build: it was deleted, and the bundle made in it.
mkdir -p "$tmp/notmine"
echo precious > "$tmp/notmine/thesis.txt"
refuses "a folder of the user's" "$build" "$tmp/notmine"
left=$(cd "$tmp/notmine" && find . -mindepth 1 | head -3 | tr '\n' ' ')
if [ "$left" != "./thesis.txt " ] || ! grep -q '^precious$' "$tmp/notmine/thesis.txt"; then
  fail "bundle.sh --out a folder of the user's changed it: $left"
fi
ln -s notmine "$tmp/link"
refuses "a link to a folder" "$build" "$tmp/link"
[ -f "$tmp/notmine/thesis.txt" ] || fail "bundle.sh --out a link deleted what it points to"

"$src/scripts/bundle.sh" --build "$build" --out "$tmp/made" --no-references || exit 1
[ -f "$tmp/made/.shadows_bundle" ] || fail "the bundle has no marker (.shadows_bundle)"
# Its own bundle with the user's results put in it: refused; without them: made again.
mkdir -p "$tmp/made/gpu_check-results"
echo "measured" > "$tmp/made/gpu_check-results/summary.md"
refuses "a bundle holding the user's results" "$build" "$tmp/made"
grep -q '^measured$' "$tmp/made/gpu_check-results/summary.md" ||
  fail "bundle.sh --out a bundle deleted the user's results in it"
rm -rf "$tmp/made/gpu_check-results"
"$src/scripts/bundle.sh" --build "$build" --out "$tmp/made/" --no-references ||
  fail "bundle.sh does not replace a bundle of its own"

# At most 60 MiB (the files' own sizes; a link counts as its few bytes).
bytes=$(du -sb "$tmp/made" | cut -f1)
echo "bundle: $bytes bytes"
[ "$bytes" -le $((60 * 1024 * 1024)) ] || fail "the bundle is $bytes bytes, over 60 MiB"

# ldd of a program lists what the loader loads for it, its libraries' own needs included,
# found as the program finds them (its DT_RPATH applies to them too).
. "$src/scripts/bundle_allowlist.sh"
for f in "$tmp"/made/bin/*; do
  [ -L "$f" ] && continue
  env -u LD_LIBRARY_PATH ldd "$f" > "$tmp/ldd.txt" 2>&1
  while read -r name arrow path rest; do
    [ "$arrow" = "=>" ] || continue
    [ "$path" = not ] || path=$(readlink -f "$path")
    case $path in
      "$tmp/made/lib/"*) ;;
      not) fail "$(basename "$f") needs $name, which is nowhere" ;;
      *) allowed "$name" || fail "$(basename "$f") needs $name from $path, outside the bundle" ;;
    esac
  done < "$tmp/ldd.txt"
  # OSMesa (and its LLVM) is loaded only for --backend osmesa, never linked.
  grep -q 'OSMesa\|LLVM' "$tmp/ldd.txt" && fail "$(basename "$f") links OSMesa or LLVM"
done

# Copied elsewhere; the bundle it was made as is gone.
mkdir -p "$tmp/fresh" "$tmp/out"
cp -a "$tmp/made" "$tmp/fresh/moved"
rm -rf "$tmp/made"
moved=$tmp/fresh/moved

# Every lesson, headless on EGL, with the source and build trees out of sight where this
# machine lets us make a mount namespace; elsewhere still from the copy.
cat > "$tmp/run_lessons.sh" << EOF
status=0
for lesson in \$(cd "$moved/bin" && ls -d [0-9][0-9]_*); do
  if ! "$moved/bin/\$lesson" --headless --backend egl --size 96x72 --frames 1 \\
       --out "$tmp/out/\$lesson.png" --report "$tmp/out/\$lesson.json" > "$tmp/out/\$lesson.txt" 2>&1; then
    echo "FAIL \$lesson does not run from the bundle:"; cat "$tmp/out/\$lesson.txt"; status=1
  fi
done
"$moved/bin/03_shadow_map_basic" --headless --backend egl-device --size 96x72 --frames 1 \\
  --no-truth --out "$tmp/out/device.png" || status=1
exit \$status
EOF
hidden="the source and build trees hidden"
if unshare -rm true 2> /dev/null; then
  # The build tree first: it may lie inside the source tree, which then hides it too.
  unshare -rm sh -c "mount -t tmpfs none '$build' && mount -t tmpfs none '$src' &&
                     cd / && ls -A '$src' | grep -q . && exit 3; sh '$tmp/run_lessons.sh'"
  status=$?
else
  hidden="the source and build trees in place (no mount namespace here)"
  sh "$tmp/run_lessons.sh"
  status=$?
fi
[ $status = 0 ] || fail "the lessons do not all run from a copied bundle ($hidden)"
lessons=$(ls "$src" | grep -c '^[0-9][0-9]_')
ran=$(ls "$tmp/out" | grep -c '^[0-9][0-9]_.*\.png$')
[ "$ran" = "$lessons" ] || fail "$ran of $lessons lessons wrote a picture"
for r in "$tmp"/out/*.json; do
  grep -q '"backend": "egl"' "$r" || fail "$(basename "$r"): not rendered by EGL"
  grep -q '"gl_errors": 0' "$r" || fail "$(basename "$r"): GL errors"
done
echo "ran $ran lessons from the copy, $hidden"

# It reads the shaders it carries: a broken copy of one is a compile error naming it.
frag=$moved/share/shadows/03_shadow_map_basic/scene.frag
cp "$frag" "$tmp/scene.frag"
echo "this is not GLSL" >> "$frag"
if "$moved/bin/03_shadow_map_basic" --headless --backend egl --size 64x48 --frames 1 --no-truth \
     --out "$tmp/out/broken.png" > "$tmp/broken.txt" 2>&1; then
  fail "a broken bundled shader did not stop lesson 03: the bundle reads shaders elsewhere"
fi
grep -q 'scene.frag' "$tmp/broken.txt" || fail "the compile error does not name scene.frag"
cp "$tmp/scene.frag" "$frag"

[ $failures = 0 ] && echo "bundle: ok" && exit 0
exit 1
