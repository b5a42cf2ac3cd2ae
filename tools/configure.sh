#!/usr/bin/env bash
# Configures and builds one CMake preset (release, debug, asan) with ccache when available.
# Usage: tools/configure.sh PRESET [cmake --build arguments...]
set -euo pipefail
preset="$1"
shift
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake --preset "$preset" "${launcher[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" "$@"
