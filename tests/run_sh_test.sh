#!/usr/bin/env bash
# ./run.sh, the front door (issue 55, 6): `./run.sh 3` is lesson 03, and on a built tree the
# launch is quiet: no line of make's, only run.sh's own. --list-params: nothing written.
set -euo pipefail
cd "$(dirname "$0")/.."
said=$(env -u DISPLAY ./run.sh 3 --list-params 2>&1)
head -1 <<<"$said" | grep -q "rendering 03_shadow_map_basic headless" ||
  { echo "./run.sh 3 did not run 03: $(head -1 <<<"$said")"; exit 1; }
grep -q "^shadow.size " <<<"$said" || { echo "./run.sh 3 --list-params listed no shadow.size"; exit 1; }
if grep -q "^setup:\|Built target\|Building\|\[ *[0-9]*%\]" <<<"$said"; then
  echo "a launch on a built tree was not quiet:"
  grep "^setup:\|Built target\|Building\|%\]" <<<"$said" | head -5
  exit 1
fi
status=0
env -u DISPLAY ./run.sh 99 >/dev/null 2>&1 || status=$?
((status == 2)) || { echo "./run.sh 99 exited $status, not 2"; exit 1; }
echo "run.sh ok"
