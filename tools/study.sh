#!/usr/bin/env bash
# The default study, a few minutes once built: installs what is missing, builds Release, and runs
# the headline scenes (dense, flat, docking, deforming, one scaling point) with one or two
# settings per backend family (scenes/sweeps/default.json), each combination in its own worker
# process, every answer checked against the exact oracle. Then compares the NURBS distance
# backends on scenes/surfaces/ (collido surface-distance) and the FRep collision test against
# polygonized meshes on scenes/frep/ (collido frep), writes each studied scene's 3D view
# (views/), and writes the dashboard. It ends by printing the "OBB tree against the field" table
# and the dashboard's path. Results: build/release/study/ (table.txt, records.jsonl,
# summary.json, times.json, views/, report.html).
#
# --full: every bundled scene and the stress scenes (the robustness matrix) with every backend
# variant (scenes/sweeps/broad.json), into build/release/study_full/.
#
# An interrupted run resumes where it stopped; a finished one is kept as OUT.previous, and the new
# report compares against it. Other arguments go to `collido study` (e.g. --repetitions 5).
set -euo pipefail
cd "$(dirname "$0")/.."
full=false
study_arguments=()
for argument in "$@"; do
  if [[ $argument == --full ]]; then full=true; else study_arguments+=("$argument"); fi
done
tools/install_deps.sh
tools/web_deps.sh
tools/configure.sh release --target collido collido_plugins
if $full; then
  out=build/release/study_full
  scenes=(scenes/*.json scenes/stress/*.json)
  sweep=scenes/sweeps/broad.json
  times=scenes/sweeps/broad.times.json
  frep_resolutions=16,32,64,128
else
  out=build/release/study
  # The headline: dense overlaps, flat and touching CAD parts, docking, deformation, scaling.
  scenes=(scenes/{bunny_vs_bunny,interlocked_tori}.json
          scenes/{gears_at_backlash,stacked_parts,stacked_plates,peg_in_hole,cad_assembly}.json
          scenes/station_docking{,_clearance,_tracked}.json
          scenes/{deforming_tori,sheet_over_bunny}.json scenes/scaling_spheres.json)
  sweep=scenes/sweeps/default.json
  times=scenes/sweeps/default.times.json
  frep_resolutions=16,32,64
fi
previous=$out.previous
# The expected time comes from the last run's wall times, else from those measured for this sweep
# on a 2-core machine (scenes/sweeps/*.times.json).
expected=$times
if [[ -f "$previous/times.json" ]]; then expected=$previous/times.json; fi
study=(build/release/collido study "${scenes[@]}" --sweep "$sweep" --out "$out"
       --expected-times "$expected")

if [[ -f "$out/plan.json" && ! -f "$out/.complete" ]]; then
  # Interrupted earlier: finish it. A different plan (scenes or sweep changed) starts afresh.
  "${study[@]}" --resume "${study_arguments[@]}" > /dev/null || status=$?
  if [[ ${status:-0} -eq 2 ]]; then
    rm -rf "$previous"
    mv "$out" "$previous"
    "${study[@]}" "${study_arguments[@]}" > /dev/null
  elif [[ ${status:-0} -ne 0 ]]; then
    exit "$status"
  fi
else
  if [[ -d "$out" ]]; then
    rm -rf "$previous"
    mv "$out" "$previous"
  fi
  "${study[@]}" "${study_arguments[@]}" > /dev/null
fi
touch "$out/.complete"
# NURBS surfaces: each surface file's pair, by the seed method and OpenCASCADE (where built) on
# the surfaces and by mesh backends on tessellations, against the certified distance; one
# process per file, so a crashing engine loses only that file's comparison.
surface_backends=nurbs:hull,nurbs:box,obbtree,obbtree[max_leaf_triangles=4],fcl:rss,fcl:obbrss
# (grep reads everything: with -q it would stop early and pipefail would see collido's SIGPIPE)
if build/release/collido backends | grep '^  occt:brep_extrema' > /dev/null; then
  surface_backends+=,occt:brep_extrema,occt:extrema_surface
fi
mkdir -p "$out/surfaces"
surface_files=()
for file in scenes/surfaces/*.json; do
  json="$out/surfaces/$(basename "$file")"
  if build/release/collido surface-distance "$file" --backends "$surface_backends" \
      --tessellations 8,32,128 --repetitions 3 --json "$json" > "${json%.json}.txt"; then
    surface_files+=(--surface-distance "$json")
  else
    echo "warning: collido surface-distance $file failed (exit $?): see ${json%.json}.txt" >&2
    if [[ -f "$json" ]]; then
      surface_files+=(--surface-distance "$json")
    fi
  fi
done
# FRep solids: each FRep file by the seed's guaranteed octree test, and mesh backends on OpenVDB
# polygonizations against it, with a ray-cast preview; one process per file.
mkdir -p "$out/frep"
frep_files=()
for file in scenes/frep/*.json; do
  json="$out/frep/$(basename "$file")"
  if build/release/collido frep "$file" --backends obbtree,fcl:obb,bullet,ode \
      --resolutions "$frep_resolutions" --repetitions 3 --json "$json" \
      --preview "${json%.json}.png" > "${json%.json}.txt"; then
    frep_files+=(--frep "$json")
  else
    echo "warning: collido frep $file failed (exit $?): see ${json%.json}.txt" >&2
    if [[ -f "$json" ]]; then
      frep_files+=(--frep "$json")
    fi
  fi
done
# The studied scenes' 3D views (collido view), each with the backends the study ran on it, linked
# from the dashboard; one view at a time, each backend in its own process.
mkdir -p "$out/views"
for file in "${scenes[@]}"; do
  [[ $file == scenes/stress/* ]] && continue
  name=$(basename "$file" .json)
  if ! build/release/collido view "$file" --results "$out" -o "$out/views/$name.html" --quiet \
      2> "$out/views/$name.txt"; then
    echo "warning: collido view $file failed: see $out/views/$name.txt" >&2
  fi
done
baseline=()
if [[ -f "$previous/.complete" ]]; then
  baseline=(--baseline "$previous")
fi
build/release/collido report "$out" "${baseline[@]}" "${surface_files[@]}" "${frep_files[@]}" \
  -o "$out/report.html" > /dev/null
# The headline: the OBB tree against the field (the whole table is in table.txt).
awk '/^The OBB tree against the field/ {show = 1} show && /^$/ {exit} show' "$out/table.txt"
echo
echo "table: $out/table.txt"
echo "dashboard: $out/report.html"
