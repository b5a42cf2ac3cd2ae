#!/usr/bin/env bash
# The cgal comparator's conformance kit. The CGAL packages it uses (AABB tree, Surface_mesh,
# rigid collision detection) are GPL-3, so it is built apart from the default build, in
# build/cgal (the 'cgal' preset, -DCOLLIDO_WITH_CGAL_GPL=ON), and a build with it is GPL as a
# whole. The kit reads the oracle's answers that the Release suite stored
# (build/release/tests/conformance/oracle_answers) when they are there, else computes them.
# Usage: tools/cgal_conformance.sh [collido_conformance options, e.g. --gtest_filter=...]
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/configure.sh cgal
oracle=()
if [[ -d build/release/tests/conformance/oracle_answers ]]; then
  oracle=(--oracle-cache=build/release/tests/conformance/oracle_answers)
fi
# The cast robot cell is left out as in the Release kit (tests/conformance/CMakeLists.txt): its
# exact answers are not in the store, and computing them here takes a minute.
build/cgal/collido_conformance --plugin=build/cgal/plugins/libcollido_plugin_cgal.so \
  "${oracle[@]}" --skip-scenes=robot_cell_cast "$@"
