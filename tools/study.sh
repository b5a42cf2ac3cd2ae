#!/usr/bin/env bash
# The default study: installs what is missing, builds Release, and runs every backend plugin
# on the bundled scenes, printing the table of answers checked against the exact oracle.
# Results: build/release/study/run.json. Extra arguments go to `collido run`.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/configure.sh release --target collido collido_plugins
mkdir -p build/release/study
build/release/collido run scenes/*.json --json build/release/study/run.json "$@"
