#!/usr/bin/env bash
# Installs web/'s npm packages (three, three-mesh-bvh: the browser's truth tracer) exactly as
# web/package-lock.json pins them, when web/node_modules does not already hold them. Called by
# scripts/setup.sh; needs node and npm (setup.sh installs them) and the npm registry.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../web"
# npm writes its own copy of the lock into node_modules: the same bytes mean nothing changed.
if [[ -f node_modules/.package-lock.json ]] &&
  node -e 'const a=require("./package-lock.json").packages,b=require("./node_modules/.package-lock.json").packages;
    for (const k of Object.keys(a)) if (k && (!b[k] || b[k].version !== a[k].version)) process.exit(1);' 2>/dev/null; then
  exit 0
fi
echo "setup: installing web/'s npm packages (npm ci)"
npm ci --no-audit --no-fund --loglevel=error
