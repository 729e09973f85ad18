#!/bin/sh
# One relocatable folder for a machine that has a GPU driver and nothing else (docs/GPU.md):
#
#   scripts/bundle.sh [--build DIR] [--out DIR] [--no-references | --short] [--glvnd]
#
#   bin/    shadows_lessons (every lesson; bin/NN_name are links to it), bench_sweep,
#           flavour_views (a lesson's views against a reference), all with an $ORIGIN/../lib
#           rpath
#   lib/    every shared library they need that is not glibc or GL/EGL (glvnd, the driver)
#   share/shadows/  the shaders (common/ and each lesson's), cases.txt (what gpu_check.sh
#           renders), reference/ (those cases on llvmpipe, rendered here through the
#           bundle's own binaries: --backend egl-device on Mesa's software device) and
#           llvmpipe/ (the benchmark CSVs the READMEs quote)
#   gpu_check.sh, GPU.md
#   glvnd/  (--glvnd) Debian's glvnd loader libraries, for a machine that has the driver's
#           libEGL_nvidia but no libEGL.so.1; gpu_check.sh uses them only then
#   .shadows_bundle  the marker: this folder is a bundle this script made, and every path
#           it made in it
#
# --out DIR is replaced whole, so it must be a folder this script may delete: one that does not
# exist yet, an empty one, or a bundle it made (its marker) holding nothing it did not make.
# Anything else (an empty path, /, a folder of the user's, a bundle with the user's files put
# into it, a link) is refused, exit 2, before anything is touched.
#
# OSMesa is not bundled: the lessons load it only for --backend osmesa, and it would bring
# LLVM (~120 MB). --no-references skips the llvmpipe references (tests/bundle_test.sh needs
# none); --short renders only those of `gpu_check.sh --short` (tests/gpu_check_test.sh).
set -eu

here=$(cd "$(dirname "$0")/.." && pwd)
build=$here/build
out=$here/build/bundle
references=1
glvnd=0
while [ $# -gt 0 ]; do
  case $1 in
    --build | --out)
      [ $# -ge 2 ] || { echo "bundle.sh: $1 needs a folder" >&2; exit 2; } ;;
  esac
  case $1 in
    --build) build=$(cd "$2" && pwd) || exit 2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --no-references) references=0; shift ;;
    --short) references=short; shift ;;
    --glvnd) glvnd=1; shift ;;
    *) echo "bundle.sh: unknown option '$1' (--build DIR, --out DIR, --no-references, --glvnd)" >&2
       exit 2 ;;
  esac
done

# The folder the bundle replaces: never one holding anything this script did not make there.
marker=.shadows_bundle
making="shadows bundle: being made by scripts/bundle.sh"
made="shadows bundle: made by scripts/bundle.sh, which replaces it whole; everything it made:"
refuse() { echo "bundle.sh: --out '$out' $*; nothing was changed" >&2; exit 2; }
while :; do  # a/b/ is a/b
  case $out in
    ?*/) out=${out%/} ;;
    *) break ;;
  esac
done
case $out in
  '') refuse "is empty: give the folder to make the bundle in (default build/bundle)" ;;
esac
if [ -L "$out" ]; then
  refuse "is a symbolic link: give the folder itself"
elif [ -e "$out" ] && [ ! -d "$out" ]; then
  refuse "exists and is not a folder"
elif [ -d "$out" ]; then
  [ "$(cd "$out" && pwd -P)" = / ] && refuse "is the root folder"
  if [ -n "$(ls -A "$out")" ]; then
    [ -f "$out/$marker" ] ||
      refuse "is not empty and is not a bundle this script made (no $marker in it): move it away or give another folder"
    # The first path in it that the bundle did not make: a finished bundle lists its own; one
    # whose making stopped holds only the top-level names a bundle has.
    foreign=$( (cd "$out" && find . -mindepth 1 | LC_ALL=C sort) |
      awk -v made="$made" '
        FNR == NR { if (FNR == 1) done = ($0 == made); else known[$0] = 1; next }
        done && !($0 in known) { print; exit }
        !done && $0 !~ /^\.\/(bin|lib|share|glvnd)(\/|$)/ &&
          $0 !~ /^\.\/(gpu_check\.sh|GPU\.md|\.shadows_bundle)$/ { print; exit }' "$out/$marker" -)
    [ -z "$foreign" ] ||
      refuse "is a bundle, but ${foreign#./} in it is not the bundle's: move that away first"
  fi
fi

programs="$build/shadows_lessons $build/bench/bench_sweep $build/tests/flavour_views"
for p in $programs; do
  [ -x "$p" ] || { echo "bundle.sh: $p is not built (cmake --build build --target" \
                        "shadows_lessons bench_sweep flavour_views)" >&2; exit 1; }
done

# Checked above: nothing, an empty folder, or a bundle holding only what this script made.
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/share/shadows"
echo "$making" > "$out/$marker"
for p in $programs; do
  # Symbols stripped: 9 MB less, and a GPU check needs no debugger.
  strip -o "$out/bin/$(basename "$p")" "$p"
done

# What glibc and the GL/EGL stack provide on the target machine; everything else is copied.
# (scripts/bundle_test.sh checks the same list.)
. "$here/scripts/bundle_allowlist.sh"
for p in "$out"/bin/*; do
  ldd "$p" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }'
done | sort -u | while read -r name path; do
  if ! allowed "$name"; then cp -L "$path" "$out/lib/$name"; fi
done

# The lessons: links named after each one, to the one program that has them all.
lessons=$(cd "$here" && ls -d [0-9][0-9]_*/ | tr -d /)
for l in $lessons; do
  ln -s shadows_lessons "$out/bin/$l"
  mkdir -p "$out/share/shadows/$l"
  # The shaders and whatever a lesson reads next to its main.cpp (not its pictures or docs).
  find "$here/$l" -maxdepth 1 -type f \( -name '*.vert' -o -name '*.frag' -o -name '*.glsl' -o -name '*.geom' \) \
    -exec cp {} "$out/share/shadows/$l/" \;
done
mkdir -p "$out/share/shadows/common"
cp -r "$here/common/shaders" "$out/share/shadows/common/"

# What gpu_check.sh renders view by view: every lesson's defaults, then the Flavour tests'
# further configurations (tests/flavour_cases.txt).
{
  for l in $lessons; do echo "$l $l"; done
  grep '^[0-9]' "$here/tests/flavour_cases.txt"
} > "$out/share/shadows/cases.txt"
# gpu_check.sh --short's: two lessons' defaults and one more configuration.
grep -E '^(03_shadow_map_basic|06_dual_texture_8bit) ' "$out/share/shadows/cases.txt" | head -3 \
  > "$out/share/shadows/cases_short.txt"

mkdir -p "$out/share/shadows/llvmpipe"
for csv in shadow_cost pcf_cost 06_dual_texture_8bit 07_multidigit_16bit 08_atmospherics \
  11_omni_cube 12_cascades; do
  cp "$here/docs/bench_$csv.csv" "$out/share/shadows/llvmpipe/"
done
cp "$here/scripts/gpu_check.sh" "$out/"
cp "$here/docs/GPU.md" "$out/"

if [ $references != 0 ]; then
  # The llvmpipe run of every configuration the GPU check renders, through the bundle itself.
  cases=$out/share/shadows/cases.txt
  [ $references = short ] && cases=$out/share/shadows/cases_short.txt
  echo "bundle.sh: rendering the llvmpipe references ($(wc -l < "$cases") cases)"
  while read -r lesson case sets; do
    set_args=""
    for s in $sets; do set_args="$set_args --set $s"; done
    # shellcheck disable=SC2086
    "$out/bin/flavour_views" "$lesson" "$out/share/shadows/reference/$case" \
      --backend egl-device --device 0 $set_args > /dev/null ||
      { echo "bundle.sh: $case does not render on llvmpipe" >&2; exit 1; }
  done < "$cases"
fi

if [ $glvnd = 1 ]; then
  # Debian's loader libraries (the machine's own driver stays the one that renders).
  tmp=$(mktemp -d)
  chmod 777 "$tmp"  # apt downloads as its own user (_apt)
  (cd "$tmp" && apt-get download libegl1 libglvnd0 libopengl0 libgles2 > /dev/null)
  for deb in "$tmp"/*.deb; do dpkg-deb -x "$deb" "$out/glvnd"; done
  rm -rf "$tmp"
fi

# The marker, finished: every path in the bundle, so that the next run deletes only those.
files=$(cd "$out" && find . -mindepth 1 | LC_ALL=C sort)
printf '%s\n%s\n' "$made" "$files" > "$out/$marker"

echo "bundle.sh: $out, $(du -sm "$out" | cut -f1) MiB"
