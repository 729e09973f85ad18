#!/usr/bin/env bash
# The students' site as plain static files, for one link a class opens: every lesson's page
# (with the truth's Web Workers and libraries), the READMEs and docs as HTML, in one folder
# that any static server serves from any path (https://host/course/shadows/ as well as /).
# The instructor's solutions are left out unless asked for.
#   scripts/publish_site.sh OUT_DIR [--with-solutions] [--no-build]
# --no-build takes build/web/site as it is (the tests'; SHADOWS_BUILD_DIR for another build
# folder); otherwise scripts/setup_pages.sh builds it first (emscripten; incremental after the
# first time).
# Publishing: web/README.md, "One link for a class" (web/publish/github-pages.yml for GitHub).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

out="" solutions=0 build=1
for arg in "$@"; do
  case $arg in
    --with-solutions) solutions=1 ;;
    --no-build) build=0 ;;
    -*) echo "publish_site: unknown option $arg (--with-solutions, --no-build)" >&2; exit 2 ;;
    *) [[ -z $out ]] || { echo "publish_site: one folder, not '$out' and '$arg'" >&2; exit 2; }
       out=$arg ;;
  esac
done
[[ -n $out ]] || { echo "usage: scripts/publish_site.sh OUT_DIR [--with-solutions] [--no-build]" >&2; exit 2; }
# Never over a folder of someone else's: empty, missing, or one this script wrote.
if [[ -e $out ]]; then
  if [[ ! -d $out ]] || { [[ ! -f $out/.shadows-site ]] && [[ -n $(ls -A "$out") ]]; }; then
    echo "publish_site: $out exists and is not a site this script wrote; give a new folder" >&2
    exit 2
  fi
fi

((build)) && scripts/setup_pages.sh
site=${SHADOWS_BUILD_DIR:-build}/web/site
[[ -f $site/index.html ]] || { echo "publish_site: no $site (run without --no-build)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out"
cp -R "$site/." "$out/"
touch "$out/.shadows-site"
touch "$out/.nojekyll"  # GitHub Pages: serve the files as they are
if ((solutions)); then
  lessons=()
  for d in [0-9][0-9]_*/; do [[ -f $d/main.cpp ]] && lessons+=("${d%/}"); done
  NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH} \
    node web/make_index.mjs . "$out" --with-solutions "${lessons[@]}"
fi
files=$(find "$out" -type f | wc -l)
size=$(du -sm "$out" | cut -f1)
echo "publish_site: $files files, $size MB in $out$( ((solutions)) && echo ', with the solutions (instructor/SOLUTIONS.html)')"
echo "publish_site: serve it from any path, e.g. python3 -m http.server -d $out 8000, then open http://localhost:8000/"
