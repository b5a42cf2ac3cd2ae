#!/usr/bin/env bash
# The bundled robot cells, regenerated: collido_make_robot_cell writes scenes/robot_cell/ (the box
# arm's URDF, its links' and the cell's meshes made by our generators, the pick-and-place
# trajectory) and, with --cast, scenes/robot_cell_cast/ (the same joints with free-form cast
# links polygonized from FRep solids, the cell with a bench and sheet-metal guards); then
# `collido import urdf` turns each into scenes/robot_cell.json and scenes/robot_cell_cast.json,
# and the cast cell's coarse waypoints into scenes/continuous/robot_cell_waypoints.json, which
# `collido check` loads.
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
  rm -rf "$out"/robot_cell "$out"/robot_cell.json "$out"/robot_cell_cast "$out"/robot_cell_cast.json \
    "$out"/continuous
  mkdir -p "$out"
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

# The cast cell: the clearance of the wrist and of each finger to everything around the arm.
"$build/collido_make_robot_cell" --cast "$out/robot_cell_cast"
cell=$out/robot_cell_cast
"$build/collido" import urdf "$cell/arm6_cast.urdf" --trajectory "$cell/pick_and_place.csv" \
  --environment "$cell"/cell/{shelf,bin_a,bin_b,fixture,bench,guard_back,guard_side}.obj \
  --clearance wrist finger_left finger_right -o "$out/robot_cell_cast.json"
"$build/collido" check "$out/robot_cell_cast.json" > /dev/null

# The cast cell's planner edges: every 8th configuration of the pick-and-place as waypoints, each
# link moved between them (StepMotion), and the first contact over each step of a finger with
# everything around the arm (one link keeps FCL's share of the default study's time small).
awk 'NR == 1 || (NR - 2) % 8 == 0' "$cell/pick_and_place.csv" > "$cell/waypoints.csv"
mkdir -p "$out/continuous"
"$build/collido" import urdf "$cell/arm6_cast.urdf" --trajectory "$cell/waypoints.csv" \
  --environment "$cell"/cell/{shelf,bin_a,bin_b,fixture,bench,guard_back,guard_side}.obj \
  --first-contact finger_left --first-contact-only -o "$out/continuous/robot_cell_waypoints.json"
"$build/collido" check "$out/continuous/robot_cell_waypoints.json" > /dev/null

if [[ $out != "$root/scenes" ]]; then
  for name in robot_cell robot_cell_cast; do
    diff -r "$root/scenes/$name" "$out/$name"
    diff "$root/scenes/$name.json" "$out/$name.json"
  done
  diff "$root/scenes/continuous/robot_cell_waypoints.json" "$out/continuous/robot_cell_waypoints.json"
  echo "robot cells: the committed files are what the generator and the import write"
fi
