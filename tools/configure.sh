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
  # Paths under the checkout are hashed relative to it, so another clone (CI's is a fresh one in
  # another folder) finds this one's objects; line tables then name the first clone's files.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi
cmake --preset "$preset" "${launcher[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" "$@"
