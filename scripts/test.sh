#!/usr/bin/env bash
# The README's test command: install what is missing, build, run every test with CTest.
# Exit status = the tests'.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
