#!/usr/bin/env bash
# Runs the test suite: installs what is missing, builds, then ctest.
#   scripts/test.sh                 default set (every label but full)
#   scripts/test.sh -L full         the long runs (published resolution)
# Extra arguments go to ctest.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo/scripts/setup.sh"
build="${DMHS_BUILD_DIR:-$repo/build}"
cd "$build"
if [ $# -eq 0 ]; then
  ctest --output-on-failure -j"$(nproc)" -LE full
else
  ctest --output-on-failure "$@"
fi
