#!/usr/bin/env bash
# Installs the Debian packages Collidoscope builds and tests with, when any is missing.
# Run as root on Debian 12 (bookworm). Usage: tools/install_deps.sh [--ci] [--slvs]  (--ci adds
# the linters CI runs: clang-format, clang-tidy; and clang with its runtime libraries for the fuzz
# targets: libclang-rt-14-dev holds libFuzzer and clang's sanitizer runtimes, which clang only
# recommends; dpkg-dev (the Debian package's dependencies) and slurm-wlm with munge (the one-node
# cluster the Slurm test starts); --slvs adds SolveSpace's libslvs, GPL-3, for the optional constraint-solver
# comparator only, tools/slvs_comparison.sh). Chromium is for the dashboard's browser test;
# Node.js and npm (when the machine has none) fetch the dashboard's front-end from the npm
# registry (tools/web_deps.sh).
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config python3
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libpng-dev
  libassimp-dev nlohmann-json3-dev libcli11-dev libfccp-dev libxxhash-dev liburdfdom-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libfcl-dev libbullet-dev libode-dev libtbb-dev libembree-dev
  libocct-modeling-algorithms-dev libocct-data-exchange-dev libopenvdb-dev
  chromium
)
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi
for option in "$@"; do
  case "$option" in
    --ci) packages+=(clang libclang-rt-14-dev clang-format clang-tidy dpkg-dev slurm-wlm munge) ;;
    --slvs) packages+=(libslvs1-dev) ;;
    *) echo "usage: tools/install_deps.sh [--ci] [--slvs]" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi
echo "Installing: ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "error: missing Debian packages and not root; run: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
