#!/usr/bin/env bash
# ./test.sh: set up, build, then run the whole test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "$@"
