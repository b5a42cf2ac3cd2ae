#!/usr/bin/env bash
# The OBB tree against the comparators and the floor, as benchmarks from one run: builds the
# release preset's collido_bench, runs the set below (medians of 5 repetitions) into a Google
# Benchmark JSON file, and prints the ratios (tools/bench_ratios.py).
# Usage: tools/bench.sh [OUTPUT.json]   (default build/release/bench/obbtree_vs_field.json)
# The committed baselines (bench/baselines/) were made with it; compare a new run with one by
# reading both tables, or with tools/bench_ratios.py --baseline FILE NEW.json.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/release/bench/obbtree_vs_field.json}"
tools/configure.sh release --target collido_bench >/dev/null
backends='obbtree,obbtree[max_leaf_triangles=4],obbtree[max_leaf_triangles=8;float_boxes=true]'
backends+=',obbtree[max_leaf_triangles=4;threads=2],fcl:obb,fcl:obbrss,bullet,ode'
scenes='bunny_vs_bunny|interlocked_tori|env_rob|meshing_gears|station_docking|gears_at_backlash|stacked_parts|flat_boxes|stacked_plates|peg_in_hole|bolted_flange|cad_assembly'
filter="^((query|floor)/.*($scenes)/(all_pairs|boolean)\$|build/.*/bunny_vs_bunny/bunny_a\$"
filter+="|scaling/.*/(all_pairs|boolean)/2\$)"
mkdir -p "$(dirname "$out")"
build/release/bench/collido_bench --backends="$backends" --benchmark_filter="$filter" \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out" --benchmark_out_format=json >/dev/null
python3 tools/bench_ratios.py "$out"
