#!/usr/bin/env bash
# The default study: installs what is missing, builds Release, and runs every backend variant
# on the bundled scenes and the stress scenes with the default sweep (scenes/sweeps/default.json),
# each combination in its own worker process, every answer checked against the exact oracle.
# Then compares the NURBS distance backends on scenes/surfaces/ (collido surface-distance) and
# the FRep collision test against polygonized meshes on scenes/frep/ (collido frep).
# Writes each bundled scene's 3D view with the backends the study ran on it (views/), prints the
# table and writes the dashboard. Results: build/release/study/ (table.txt, records.jsonl,
# summary.json, robustness.txt, views/, report.html). An interrupted run resumes where it
# stopped; a finished one is kept as build/release/study.previous and the new report compares
# against it.
# Extra arguments go to `collido study` (e.g. --repetitions 5).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/web_deps.sh
tools/configure.sh release --target collido collido_plugins
out=build/release/study
previous=build/release/study.previous
# The bundled scenes and the stress scenes (one per robustness category: the robustness matrix).
study=(build/release/collido study scenes/*.json scenes/stress/*.json
       --sweep scenes/sweeps/default.json --out "$out")

if [[ -f "$out/plan.json" && ! -f "$out/.complete" ]]; then
  # Interrupted earlier: finish it. A different plan (scenes or sweep changed) starts afresh.
  "${study[@]}" --resume "$@" || status=$?
  if [[ ${status:-0} -eq 2 ]]; then
    rm -rf "$previous"
    mv "$out" "$previous"
    "${study[@]}" "$@"
  elif [[ ${status:-0} -ne 0 ]]; then
    exit "$status"
  fi
else
  if [[ -d "$out" ]]; then
    rm -rf "$previous"
    mv "$out" "$previous"
  fi
  "${study[@]}" "$@"
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
      --resolutions 16,32,64,128 --repetitions 3 --json "$json" \
      --preview "${json%.json}.png" > "${json%.json}.txt"; then
    frep_files+=(--frep "$json")
  else
    echo "warning: collido frep $file failed (exit $?): see ${json%.json}.txt" >&2
    if [[ -f "$json" ]]; then
      frep_files+=(--frep "$json")
    fi
  fi
done
# The scenes' 3D views (collido view), each with the backends the study ran on it, linked from
# the dashboard; one view at a time, each backend in its own process.
mkdir -p "$out/views"
for file in scenes/*.json; do
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
  -o "$out/report.html"
