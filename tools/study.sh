#!/usr/bin/env bash
# The default study, a few minutes once built: installs what is missing, builds Release, and runs
# the headline scenes (dense, flat, docking, deforming, one scaling point) with one or two
# settings per backend family (scenes/sweeps/default.json), each combination in its own worker
# process, every answer checked against the exact oracle; in the same study the NURBS distance
# backends on scenes/surfaces/ (as collido surface-distance compares them) and the FRep collision
# test against polygonized meshes on scenes/frep/ (as collido frep does), the seed method and each
# backend in a worker of its own (the sweep's "surfaces" and "frep"). Then it writes each studied
# scene's 3D view (views/) and the dashboard. It ends by printing the "OBB tree against the field" table
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
# What the study runs, and no more: the conformance kit (`collido conformance PLUGIN.so`) is built
# by the test command, or by `cmake --build build/release --target collido_conformance`.
tools/configure.sh release --target collido collido_plugins
if $full; then
  out=build/release/study_full
  scenes=(scenes/*.json scenes/stress/*.json)
  sweep=scenes/sweeps/broad.json
  times=scenes/sweeps/broad.times.json
else
  out=build/release/study
  # The headline: dense overlaps, flat and touching CAD parts, docking, deformation, scaling,
  # what the scenes' needs save (boolean only, mostly static, distance only), and a robot's
  # pick-and-place in a cluttered cell (self-collision, robot against the cell, clearance); and
  # between the frames, the first contact over each step (a thin part crossing a plate, the
  # docking approach, a peg sliding into its sleeve's wall, a robot's edges between waypoints).
  scenes=(scenes/{bunny_vs_bunny,interlocked_tori}.json
          scenes/{gears_at_backlash,stacked_parts,stacked_plates,peg_in_hole,cad_assembly}.json
          scenes/station_docking{,_clearance,_tracked}.json
          scenes/{deforming_tori,sheet_over_bunny}.json scenes/scaling_spheres.json
          scenes/{bunny_teapot_boolean,cad_assembly_held,env_rob_clearance}.json
          scenes/robot_cell.json
          scenes/continuous/{thin_crossing,docking_approach,peg_side_contact,robot_cell_waypoints}.json)
  sweep=scenes/sweeps/default.json
  times=scenes/sweeps/default.times.json
fi
previous=$out.previous
# The expected time comes from the last run's wall times, else from those measured for this sweep
# on a 2-core machine (scenes/sweeps/*.times.json).
expected=$times
if [[ -f "$previous/times.json" ]]; then expected=$previous/times.json; fi
# The exact answers live beside the study folder, not in it: a new run moves the folder to
# $previous, and would otherwise compute every scene's oracle again (kept by each scene's digest,
# so a changed scene gets new ones).
study=(build/release/collido study "${scenes[@]}" --surfaces scenes/surfaces/*.json
       --frep scenes/frep/*.json --sweep "$sweep" --out "$out" --expected-times "$expected"
       --oracle-store build/release/oracle)

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
# Finished; the commit it ran (tools/publish_results.sh names it on the published page).
git rev-parse --short HEAD 2>/dev/null > "$out/.complete" || touch "$out/.complete"
# The studied scenes' 3D views (collido view), each with the backends the study ran on it, linked
# from the dashboard; one view at a time, each backend in its own process. A view shows answers,
# not times: the previous run's page is kept when nothing it is made from changed (the program,
# the plugins, the viewer's front-end, the scene's files as the plan digests them, and the
# settings run on it), and remade otherwise.
mkdir -p "$out/views"
tools_digest=$({ sha256sum build/release/collido build/release/plugins/*.so
                 find web/view -type f -print0 | sort -z | xargs -0 sha256sum; } | sha256sum)
for file in "${scenes[@]}"; do
  [[ $file == scenes/stress/* ]] && continue
  name=$(basename "$file" .json)
  settings=$(python3 - "$out/plan.json" "$file" <<'PY'
import json, os, sys
plan = json.load(open(sys.argv[1], encoding="utf-8"))
path = os.path.abspath(sys.argv[2])
for c in plan["combinations"]:
    if c.get("scene_path") == path:
        print(c["backend"], c["scene_digest"], c["plugin"], c["resolution"], c["needs"])
PY
)
  key=$(printf '%s\n%s\n' "$tools_digest" "$settings" | sha256sum | cut -c1-64)
  if [[ -n $settings && -f "$previous/views/$name.html" &&
        "$(cat "$previous/views/$name.key" 2>/dev/null)" == "$key" ]]; then
    cp "$previous/views/$name.html" "$previous/views/$name.key" "$out/views/"
    cp "$previous/views/$name.txt" "$out/views/" 2>/dev/null || true
    continue
  fi
  if build/release/collido view "$file" --results "$out" --oracle-store build/release/oracle \
      -o "$out/views/$name.html" --quiet 2> "$out/views/$name.txt"; then
    echo "$key" > "$out/views/$name.key"
  else
    echo "warning: collido view $file failed: see $out/views/$name.txt" >&2
  fi
done
baseline=()
if [[ -f "$previous/.complete" ]]; then
  baseline=(--baseline "$previous")
fi
build/release/collido report "$out" "${baseline[@]}" -o "$out/report.html" > /dev/null
# The headline: the field table, found by its key (the whole table is in table.txt).
python3 - "$out/sections.json" <<'PY'
import json, sys
for section in json.load(open(sys.argv[1], encoding="utf-8"))["sections"]:
    if section["key"] == "field":
        print(section["heading"] + ":\n" + section["text"], end="")
PY
echo
echo "table: $out/table.txt"
echo "dashboard: $out/report.html"
