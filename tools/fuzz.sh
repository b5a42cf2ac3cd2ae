#!/usr/bin/env bash
# Bounded fuzzing: builds the libFuzzer targets of tests/fuzz/ in the sanitizer build (the 'asan'
# preset: clang, ASan + UBSan, coverage instrumentation; the test suite's build too, so nothing is
# compiled twice) and runs each for SECONDS over a scratch copy of its seed corpus, so tests/fuzz/corpus/
# is never written. Fails when any target crashes, leaks, hits undefined behaviour, breaks its
# own check, takes more than 30 s on one input or more than 2 GB of memory.
# Usage: tools/fuzz.sh [SECONDS per target, default 60] [TARGET...]  (default: every target)
# Environment: COLLIDO_FUZZ_JOBS: build jobs (default: every core). COLLIDO_FUZZ_PARALLEL: targets
# fuzzed at once (default: every core; each fuzzer uses one). COLLIDO_FUZZ_SEED: libFuzzer's
# random seed (default: a new one each run). With a fixed seed the inputs tried are one fixed
# sequence, of which a run covers as much as its time allows: CI fixes the seed, so its verdict
# depends on the code alone, and a longer run with the same seed here covers what CI will try.
# Exploring with new seeds (the default) is how new findings are made; each becomes a
# regression seed in tests/fuzz/corpus/.
# Each run leaves build/asan/fuzz_runs/<target>/: log.txt, corpus/ (seeds plus what the run
# added) and artifacts/ (crash-*, leak-*, timeout-*, oom-*: reproducers; replay one with
# build/asan/fuzzers/<target> FILE). docs/FUZZING.md says what each target checks.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
[[ $# -gt 0 ]] && shift
targets=("$@")
if [[ ${#targets[@]} -eq 0 ]]; then
  targets=(scene_json_fuzz mesh_import_fuzz tree_query_fuzz surface_json_fuzz frep_json_fuzz)
fi
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [[ "$seconds" -eq 0 ]]; then
  echo "usage: tools/fuzz.sh [SECONDS per target] [TARGET...]" >&2
  exit 2
fi

tools/configure.sh asan --target collido_fuzzers -j "${COLLIDO_FUZZ_JOBS:-$(nproc)}"

export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
for target in "${targets[@]}"; do
  if [[ ! -x "build/asan/fuzzers/$target" || ! -d "tests/fuzz/corpus/$target" ]]; then
    echo "error: no fuzz target '$target' (or no tests/fuzz/corpus/$target)" >&2
    exit 2
  fi
done

# One target's run; its exit status is left in $run/status, read when every run has ended.
fuzz_target() {
  local target="$1" fuzzer="build/asan/fuzzers/$1" seeds="tests/fuzz/corpus/$1"
  local run="build/asan/fuzz_runs/$1" status=0 seed=()
  [[ -n "${COLLIDO_FUZZ_SEED:-}" ]] && seed=(-seed="$COLLIDO_FUZZ_SEED")
  "$fuzzer" "$run/corpus" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
    "${seed[@]}" -print_final_stats=1 -artifact_prefix="$run/artifacts/" \
    >"$run/log.txt" 2>&1 || status=$?
  echo "$status" >"$run/status"
}

# Each fuzzer is one process on one core, so as many run at once as there are cores
# (COLLIDO_FUZZ_PARALLEL): each still gets its SECONDS, and the step's wall time shrinks.
parallel="${COLLIDO_FUZZ_PARALLEL:-$(nproc)}"
running=0
for target in "${targets[@]}"; do
  seeds="tests/fuzz/corpus/$target"
  run="build/asan/fuzz_runs/$target"
  rm -rf "$run"
  mkdir -p "$run/corpus" "$run/artifacts"
  cp -R "$seeds/." "$run/corpus/"
  echo
  echo "--- $target: ${seconds}s over $(find "$seeds" -type f | wc -l) seeds (log: $run/log.txt)"
  fuzz_target "$target" &
  running=$((running + 1))
  if [[ $running -ge $parallel ]]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

summary=()
failed=0
for target in "${targets[@]}"; do
  seeds="tests/fuzz/corpus/$target"
  run="build/asan/fuzz_runs/$target"
  status=$(cat "$run/status" 2>/dev/null || echo "?")
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$run/log.txt" | tail -n 1)
  coverage=$(grep -oE 'cov: [0-9]+' "$run/log.txt" | tail -n 1 | cut -d' ' -f2)
  added=$(( $(find "$run/corpus" -type f | wc -l) - $(find "$seeds" -type f | wc -l) ))
  line="$target: ${runs:-?} inputs, coverage ${coverage:-?}, $added new corpus entries"
  if [[ $status == 0 ]]; then
    summary+=("PASS $line")
  else
    failed=1
    artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$run/log.txt" | tail -n 1)
    first=$(grep -m 1 -E 'ERROR:|runtime error:|disagrees|broke its promise|terminate called' \
      "$run/log.txt" || true)
    summary+=("FAIL $line (exit $status)")
    summary+=("       ${first:-see the log}")
    summary+=("       reproducer: ${artifact:-none written}; log: $run/log.txt")
    grep -E -A 40 'ERROR:|runtime error:|disagrees|broke its promise|terminate called' \
      "$run/log.txt" | head -n 60 || true
  fi
done

echo
echo "=== fuzzing summary (${seconds}s per target, $parallel at a time)"
printf '%s\n' "${summary[@]}"
exit $failed
