#!/usr/bin/env bash
# The bundled robot cell, regenerated: collido_make_robot_cell writes scenes/robot_cell/ (the arm's
# URDF, its links' and the cell's meshes made by our generators, the pick-and-place trajectory),
# then `collido import urdf` turns them into scenes/robot_cell.json, which `collido check` loads.
#
#   tools/make_robot_cell.sh [BUILD_DIR]            rewrite the committed files (build/release)
#   tools/make_robot_cell.sh BUILD_DIR --check DIR  write into DIR and fail unless the files equal
#                                                   the committed ones (ctest robot_cell.regenerates)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
out=$root/scenes
if [[ ${2:-} == --check ]]; then
  out=${3:?--check needs a folder}
  rm -rf "$out/robot_cell" "$out/robot_cell.json" && mkdir -p "$out"
fi
if [[ ! -x $build/collido_make_robot_cell ]]; then
  echo "error: no $build/collido_make_robot_cell (a build with COLLIDO_BUILD_TESTS=ON has it)" >&2
  exit 2
fi
"$build/collido_make_robot_cell" "$out/robot_cell"
cell=$out/robot_cell
"$build/collido" import urdf "$cell/arm6.urdf" --trajectory "$cell/pick_and_place.csv" \
  --environment "$cell"/cell/{shelf,bin_a,bin_b,fixture}.obj -o "$out/robot_cell.json"
"$build/collido" check "$out/robot_cell.json" > /dev/null
if [[ $out != "$root/scenes" ]]; then
  diff -r "$root/scenes/robot_cell" "$cell"
  diff "$root/scenes/robot_cell.json" "$out/robot_cell.json"
  echo "robot cell: the committed files are what the generator and the import write"
fi
