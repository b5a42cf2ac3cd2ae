#!/usr/bin/env bash
# Installs a built tree into a temporary prefix and uses it as a stranger would: builds the
# examples (examples/brute_force_plugin, examples/obbtree_query, the latter as without assimp, and
# examples/record_fcl_app where FCL is installed) out of tree, from copies, with
# find_package(Collidoscope), and a small program on Collidoscope::core; runs them; studies the
# recording the FCL example makes; runs the installed tool on an installed scene (a run and a 3D
# view) and the installed conformance kit on the example plugin. CTest runs it
# (install.sdk_examples_and_kit); by hand:
#   tools/check_install.sh build/release [WORK_DIR]
# Extra arguments after WORK_DIR go to `collido conformance` (e.g. --scenes-dir DIR).
set -euo pipefail
build=$(realpath "$1")
source_dir=$(realpath "$(dirname "$0")/..")
work=${2:-$(mktemp -d)}
shift $(( $# < 2 ? $# : 2 ))
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
prefix=$work/prefix

# The examples compile through ccache where it is installed, with paths taken relative to the work
# folder, so that a later run, in this clone or another, finds their objects again.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$work" CCACHE_NOHASHDIR=1
fi

echo "== install into $prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"

# Copies, so that nothing can reach back into the source tree. The OBB tree example is configured
# as on a machine without assimp: the obbtree component must not need the mesh readers.
for example in brute_force_plugin obbtree_query; do
  echo "== build examples/$example out of tree against the install"
  cp -r "$source_dir/examples/$example" "$work/$example"
  no_assimp=()
  [[ $example == obbtree_query ]] && no_assimp=(--no-warn-unused-cli -DCMAKE_DISABLE_FIND_PACKAGE_assimp=TRUE)
  cmake -S "$work/$example" -B "$work/$example/build" "${no_assimp[@]}" \
        -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" > "$work/$example.configure.log"
  cmake --build "$work/$example/build" > "$work/$example.build.log"
done

# A plugin's build needs Eigen and nothing else of Collidoscope's dependencies.
if grep -E "^(CGAL|TBB|assimp|Boost|PNG|Imath|nlohmann_json)_DIR:" \
     "$work/brute_force_plugin/build/CMakeCache.txt"; then
  echo "error: find_package(Collidoscope COMPONENTS plugin_api) looked for more than Eigen" >&2
  exit 1
fi

# The OBB tree as a library needs Eigen, CGAL (which brings Boost's headers) and oneTBB, and none
# of the packages of the mesh readers, scenes or reports.
if grep -E "^(assimp|PNG|Imath|nlohmann_json)_DIR:" \
     "$work/obbtree_query/build/CMakeCache.txt"; then
  echo "error: find_package(Collidoscope COMPONENTS obbtree) looked for more than Eigen, CGAL and TBB" >&2
  exit 1
fi

echo "== a program on Collidoscope::core (all components), out of tree"
mkdir -p "$work/core_consumer"
cat > "$work/core_consumer/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(core_consumer LANGUAGES CXX)
find_package(Collidoscope 0.1 REQUIRED)
add_executable(core_consumer main.cpp)
target_link_libraries(core_consumer PRIVATE Collidoscope::core)
CMAKE
cat > "$work/core_consumer/main.cpp" <<'CPP'
#include <cstdio>
#include <collido/scene/scene.h>
int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const auto scene = collido::loadScene(argv[1]);
  if (!scene.ok()) return 1;
  std::printf("%s: %zu objects, %zu queries\n", scene.value().name.c_str(),
              scene.value().objects.size(), scene.value().queries.size());
}
CPP
cmake -S "$work/core_consumer" -B "$work/core_consumer/build" \
      -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" > "$work/core_consumer.configure.log"
cmake --build "$work/core_consumer/build" > "$work/core_consumer.build.log"
"$work/core_consumer/build/core_consumer" "$prefix/share/collido/scenes/interlocked_tori.json"

echo "== run the OBB tree example"
"$work/obbtree_query/build/obbtree_query" | tee "$work/obbtree_query.out"
grep -Eq "shifted by 0.2: [1-9][0-9]* intersecting" "$work/obbtree_query.out"
grep -q "shifted by 2.0: 0 intersecting" "$work/obbtree_query.out"

echo "== the installed collido: its plugins and a bundled scene"
"$prefix/bin/collido" backends > "$work/backends.out"
grep -q "obbtree" "$work/backends.out"
"$prefix/bin/collido" run "$prefix/share/collido/scenes/interlocked_tori.json" \
  --backends obbtree > "$work/run.out"
cat "$work/run.out"
"$prefix/bin/collido" view "$prefix/share/collido/scenes/interlocked_tori.json" \
  --backends obbtree -o "$work/view.html" > /dev/null
grep -q "OrbitControls" "$work/view.html"

# FRep solids are polygonized by OpenVDB in a module the installed tool opens on first use.
"$prefix/bin/collido" frep "$prefix/share/collido/scenes/frep/seed_quadric.json" --repetitions 1 \
  --backends obbtree --resolutions 12 > "$work/frep.out"
grep -Eq "obbtree +12 .* ok" "$work/frep.out"

# An application recorded with Collidoscope::record (Eigen only), then its recording studied: the
# path a user takes from their own FCL loop to a study. Only where the build had FCL.
if [[ -x "$build/examples/record_fcl_app/record_fcl_app" ]]; then
  echo "== build examples/record_fcl_app against the install, record its run, study the recording"
  cp -r "$source_dir/examples/record_fcl_app" "$work/record_fcl_app"
  cmake -S "$work/record_fcl_app" -B "$work/record_fcl_app/build" \
        -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" > "$work/record_fcl_app.configure.log"
  cmake --build "$work/record_fcl_app/build" > "$work/record_fcl_app.build.log"
  if grep -E "^(CGAL|TBB|assimp|PNG|Imath|nlohmann_json)_DIR:" \
       "$work/record_fcl_app/build/CMakeCache.txt"; then
    echo "error: find_package(Collidoscope COMPONENTS record) looked for more than Eigen" >&2
    exit 1
  fi
  "$work/record_fcl_app/build/record_fcl_app" "$work/recording"
  "$prefix/bin/collido" study "$work/recording/scene.json" --backends obbtree fcl:obbrss \
    --repetitions 1 --quiet --out "$work/recording_study" > "$work/recording_study.out"
  cat "$work/recording_study/table.txt"
  grep -q '"backend":"fcl' "$work/recording_study/records.jsonl"
fi

echo "== the installed conformance kit on the example plugin"
"$prefix/bin/collido" conformance "$work/brute_force_plugin/build/libbrute_force.so" "$@"
echo "install check passed ($work)"
