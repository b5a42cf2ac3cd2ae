#!/usr/bin/env bash
# The constraint solver against SolveSpace's libslvs (GPL-3, so built apart from the default
# build, in build/slvs with COLLIDO_WITH_SLVS=ON): installs libslvs1-dev when missing, builds
# collido_slvs_comparison and runs it, writing build/slvs/comparison.txt and comparison.json.
# Usage: tools/slvs_comparison.sh [collido_slvs_comparison options, e.g. --points 2 20 --seeds 1]
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh --slvs
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build/slvs -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOLLIDO_WITH_SLVS=ON \
  -DCOLLIDO_BUILD_TESTS=OFF -DCOLLIDO_BUILD_BENCHMARKS=OFF -DCOLLIDO_WARNINGS_AS_ERRORS=ON \
  "${launcher[@]}" >/dev/null
cmake --build build/slvs --target collido_slvs_comparison -j "$(nproc)"
build/slvs/collido_slvs_comparison --json build/slvs/comparison.json "$@" |
  tee build/slvs/comparison.txt
