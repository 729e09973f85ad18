#!/usr/bin/env bash
# Installs what the web pages need (emscripten and chromium from Debian), fetches Dear ImGui's
# sources (Debian's source package of the libimgui-dev the native build uses: the binary
# package has no imgui.cpp), then configures and builds the pages into build/web/site/.
# Called by scripts/setup.sh (so ./test.sh's browser tests have them) and by ./run.sh web.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(emscripten chromium nodejs python3-glad libglm-dev libstb-dev libimgui-dev curl xz-utils)
source scripts/packages.sh
ensure_packages setup_pages "${packages[@]}"
# Debian's emscripten runs its JS tools with the system node, whose modules live here.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

# ImGui: the .orig tarball of the installed libimgui-dev's source version, checked against the
# SHA-256 its .dsc lists, unpacked once into build/web-deps/. Plain downloads from Debian's
# pool: the machine's apt configuration is left as it is.
version=$(dpkg-query -W -f='${source:Version}' libimgui-dev)  # e.g. 1.86+ds-1
upstream=${version%-*}                                         # 1.86+ds
deps=build/web-deps
imgui_dir=$deps/imgui-${upstream%%+*}
if [[ ! -f $imgui_dir/imgui.cpp ]]; then
  mkdir -p "$deps"
  pool=${SHADOWS_DEBIAN_POOL:-http://deb.debian.org/debian/pool/main/i/imgui}
  echo "setup_pages: fetching Dear ImGui $version sources from $pool"
  curl -sSfL -o "$deps/imgui.dsc" "$pool/imgui_${version}.dsc"
  curl -sSfL -o "$deps/imgui.orig.tar.xz" "$pool/imgui_${upstream}.orig.tar.xz"
  want=$(awk '/^Checksums-Sha256:/ {s=1; next} /^[^ ]/ {s=0} s && $3 ~ /orig\.tar/ {print $1}' \
         "$deps/imgui.dsc")
  have=$(sha256sum "$deps/imgui.orig.tar.xz" | cut -d' ' -f1)
  if [[ -z $want || $want != "$have" ]]; then
    echo "setup_pages: imgui_${upstream}.orig.tar.xz does not match its .dsc (sha256 $have)"
    exit 1
  fi
  tar -xf "$deps/imgui.orig.tar.xz" -C "$deps"
  [[ -f $imgui_dir/imgui.cpp ]] || { echo "setup_pages: no $imgui_dir/imgui.cpp"; exit 1; }
fi

jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/web/CMakeCache.txt ]]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache
                                           -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  emcmake cmake -S web -B build/web -DCMAKE_BUILD_TYPE=Release \
    -DIMGUI_SOURCE_DIR="$PWD/$imgui_dir" "${launcher[@]}" >/dev/null
fi
echo "setup_pages: building the pages into build/web/site/ with $jobs jobs"
cmake --build build/web -j"$jobs"
