#!/usr/bin/env bash
# Installs the dashboard's front-end into web/node_modules from the npm registry, exactly as
# web/package-lock.json pins it: Vega, Vega-Lite and vega-embed (inlined into every report) and
# playwright-core (the browser test). Does nothing when it is already up to date.
set -euo pipefail
cd "$(dirname "$0")/../web"
if ! command -v npm >/dev/null 2>&1; then
  echo "error: npm not found; run tools/install_deps.sh (as root) first" >&2
  exit 1
fi
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
  npm ci --no-audit --no-fund --loglevel=error
fi
