#!/usr/bin/env bash
# Collidoscope is BSD-3-Clause; GPL code may only enter through an optional part that is off by
# default. CGAL mixes LGPL packages (kernels, intersections, IO) with GPL ones (e.g. polygon mesh
# processing), so this lists every CGAL header a default build compiled and fails on a GPL one.
# Usage: tools/check_licences.sh [BUILD_DIR]   (default build/release, a Ninja build)
set -euo pipefail
build="${1:-build/release}"
headers=$(ninja -C "$build" -t deps | grep -o '/usr/include/CGAL/[^ ]*' | sort -u)
if [[ -z "$headers" ]]; then
  echo "no CGAL headers found in $build's dependency log; build it first" >&2
  exit 1
fi
gpl=$(echo "$headers" | xargs grep -l 'SPDX-License-Identifier: GPL' || true)
if [[ -n "$gpl" ]]; then
  echo "GPL-licensed CGAL headers in the default build:" >&2
  echo "$gpl" >&2
  exit 1
fi
# libslvs (GPL-3) is for the optional constraint-solver comparator only (COLLIDO_WITH_SLVS).
if ninja -C "$build" -t deps | grep -q '/usr/include/slvs.h'; then
  echo "the default build compiled slvs.h (GPL-3): COLLIDO_WITH_SLVS must stay off" >&2
  exit 1
fi
echo "licences: $(echo "$headers" | wc -l) CGAL headers compiled, none GPL; no libslvs"
