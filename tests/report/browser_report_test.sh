#!/usr/bin/env bash
# The dashboard in a real browser: runs a small study (two backends, needs declared and every,
# two resolutions so the scaling view has curves, and a small stress scene so the robustness
# matrix has cells, ODE's all-pairs ones unsupported, a deforming scene for the view over
# time, and a small scene posed from tracked markers; the tori's distance query fills the distance
# view; a NURBS comparison on the sphere zones fills the surfaces view; an FRep comparison with
# its preview picture fills the FRep view; the thin crossing, with the runner's sub-steps beside the
# tree's own answer, fills the first-contact view), writes its report with
# itself as the
# baseline, and opens it in headless Chromium (web/tests/report.test.mjs): every chart drawn,
# no console error, no network request.
# Usage: browser_report_test.sh COLLIDO_EXECUTABLE SOURCE_DIR WORK_DIR
set -euo pipefail
collido="$1"
source_dir="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"
cat > "$work/sweep.json" <<'JSON'
{
  "backends": [{"variant": "obbtree", "options": {"max_leaf_triangles": [1, 4]}}, "ode",
               {"variant": "obbtree", "options": {"substeps": [4]}, "scenes": ["thin_crossing"]}],
  "resolutions": [0.5, 1],
  "needs": ["declared", "every"],
  "repetitions": 1
}
JSON
cat > "$work/stress_touching.json" <<'JSON'
{
  "name": "stress_touching_small",
  "stress": {"category": "touching", "severities": [0, 2], "cases_per_severity": 3, "seed": 1}
}
JSON
# A sphere passing through another, posed from four noisy markers (a contact frame can flip).
cat > "$work/tracked.json" <<'JSON'
{"name": "tracked_small", "frames": 8, "objects": [
  {"name": "ball", "shape": {"generator": "sphere", "radius": 0.5, "slices": 12, "stacks": 6}},
  {"name": "probe", "shape": {"generator": "sphere", "radius": 0.3, "slices": 12, "stacks": 6},
   "motion": {"linear": {"from": {"translation": [-1.2, 0, 0]}, "to": {"translation": [1.2, 0, 0]}}},
   "markers": {"layout": {"1": [0.3, 0, 0], "2": [0, 0.3, 0], "3": [0, 0, 0.3], "4": [-0.3, 0, 0]},
               "generate": {"noise": 0.02, "seed": 2}}}],
 "queries": [{"name": "touch", "a": "ball", "b": "probe", "kind": "boolean"}]}
JSON
"$collido" study "$source_dir/scenes/interlocked_tori.json" "$work/stress_touching.json" \
  "$source_dir/scenes/deforming_tori.json" "$work/tracked.json" \
  "$source_dir/scenes/continuous/thin_crossing.json" \
  --sweep "$work/sweep.json" --out "$work/study" --quiet > "$work/table.txt"
"$collido" pose-error "$work/tracked.json" --object probe --layouts spread,given \
  --markers 3,4 --trials 20 --json "$work/pose_error.json" > /dev/null
"$collido" surface-distance "$source_dir/scenes/surfaces/sphere_zones.json" --seed-only \
  --backends nurbs:hull,obbtree --tessellations 8,16 --repetitions 1 \
  --json "$work/surfaces.json" > /dev/null
"$collido" frep "$source_dir/scenes/frep/seed_quadric.json" --repetitions 1 \
  --backends obbtree --resolutions 8,16 --json "$work/frep.json" \
  --preview "$work/frep.png" --preview-size 96,72 > /dev/null
# A scene's 3D view beside the study: the dashboard links it ("Scenes in 3D"). No leak check
# under AddressSanitizer in the view's processes (browser_view_test.sh says why).
mkdir -p "$work/study/views"
ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$collido" view "$work/tracked.json" --results "$work/study" -o "$work/study/views/tracked_small.html" \
  --quiet
"$collido" report "$work/study" --baseline "$work/study" --pose-error "$work/pose_error.json" \
  --surface-distance "$work/surfaces.json" --frep "$work/frep.json" -o "$work/report.html"
COLLIDO_REPORT_HTML="$work/report.html" COLLIDO_TABLE_TXT="$work/study/table.txt" \
COLLIDO_EXPECT_VIEWS="time-vs-error,distance-error,contact-error,first-contact-error,surfaces,frep,robustness,time-distribution,deforming,tracking,pose-error,memory,scaling,scaling-memory,needs,comparison" \
COLLIDO_EXPECT_SECTION_TEXT="between-frames=obbtree[substeps,robustness=unsupported,robustness=touching,scene-views=tracked_small,what-to-pick=smallest exact,failures=Not applicable" \
COLLIDO_REPORT_SCREENSHOT="$work/report.png" \
  node --test "$source_dir/web/tests/report.test.mjs"
