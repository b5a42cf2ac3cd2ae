#!/usr/bin/env bash
# clang-tidy on the project's own sources (core/, backends/, bench/; not tests, not the GPL cgal
# comparator), each file compiled alone: the 'tidy' preset is configured, never built, for its
# compile commands (the Release build compiles sources in batches: cmake/CollidoUnity.cmake).
#   tools/tidy.sh               every file (tools/clang_tidy.py skips files it found clean before)
#   tools/tidy.sh --full        every file; when all are clean, records HEAD in .ci/clang_tidy_clean
#                               (commit it, so that CI's --since-clean starts there)
#   tools/tidy.sh --since-clean only the files a change since .ci/clang_tidy_clean's commit can have
#                               affected, read from build/release's dependency log (CI)
# The analyzer runs in its shallow mode (less inlining across calls): its full depth through
# CGAL's and Eigen's templates was half of a full run's 23 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
cmake --preset tidy >/dev/null
mapfile -t sources < <(git ls-files 'core/*.cpp' 'backends/*.cpp' 'bench/*.cpp' | grep -v '/tests/' |
  grep -v '^backends/cgal/')
options=(-p build/tidy -j "$(nproc)"
         --extra-arg=-Xclang --extra-arg=-analyzer-config --extra-arg=-Xclang --extra-arg=mode=shallow)
case "$mode" in
  "") ;;
  --full)
    options+=(--record-clean .ci/clang_tidy_clean) ;;
  --since-clean)
    if [[ -s .ci/clang_tidy_clean && -f build/release/build.ninja ]]; then
      options+=(--since "$(tr -d '[:space:]' < .ci/clang_tidy_clean)" --deps build/release)
    fi ;;
  *) echo "usage: tools/tidy.sh [--full | --since-clean]" >&2; exit 2 ;;
esac
mkdir -p build
if ! tools/clang_tidy.py "${options[@]}" "${sources[@]}" 2>&1 | tee build/clang-tidy.log; then
  echo "clang-tidy found problems (build/clang-tidy.log)"
  exit 1
fi
