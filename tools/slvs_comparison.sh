#!/usr/bin/env bash
# The constraint solver against SolveSpace's libslvs (GPL-3, so built apart from the default
# build, in build/slvs: the 'slvs' preset): installs libslvs1-dev when missing, builds
# collido_slvs_comparison and runs it, writing build/slvs/comparison.txt and comparison.json.
# Usage: tools/slvs_comparison.sh [collido_slvs_comparison options, e.g. --points 2 20 --seeds 1]
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh --slvs
tools/configure.sh slvs
build/slvs/collido_slvs_comparison --json build/slvs/comparison.json "$@" |
  tee build/slvs/comparison.txt
