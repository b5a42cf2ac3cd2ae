#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds Release with tests, runs CTest.
# Extra arguments go to ctest (e.g. -R obbtree).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/web_deps.sh
tools/configure.sh release
ctest --preset release "$@"
