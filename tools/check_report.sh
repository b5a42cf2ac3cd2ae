#!/usr/bin/env bash
# Checks a study's dashboard in headless Chromium, as a reader opens it: every chart drawn with no
# console error or network request, no legend over ten entries, the header's counts linked, the
# filters working, the "What to pick" rows the same settings as the study's table.txt, and the
# page showing within a time bound (default 5000 ms; run it on a quiet machine). The report is
# written anew from the study (collido report), so the check sees the current dashboard code.
# Usage: tools/check_report.sh [STUDY_DIR] [--limit-ms N] [--screenshot FILE]
#   STUDY_DIR defaults to build/release/study (tools/study.sh); tools/study.sh --full writes
#   build/release/study_full. --screenshot saves the top of the page (1400 x 1000).
set -euo pipefail
cd "$(dirname "$0")/.."
study=build/release/study
limit=5000
screenshot=
while [[ $# -gt 0 ]]; do
  case $1 in
    --limit-ms)
      if [[ $# -lt 2 || ! $2 =~ ^[0-9]+$ ]]; then
        echo "error: --limit-ms needs a whole number of milliseconds" >&2; exit 2
      fi
      limit=$2; shift 2 ;;
    --screenshot)
      if [[ $# -lt 2 ]]; then echo "error: --screenshot needs a file" >&2; exit 2; fi
      screenshot=$(realpath -m "$2"); shift 2 ;;
    -*) echo "error: unknown option $1" >&2; exit 2 ;;
    *) study=$1; shift ;;
  esac
done
if [[ ! -f $study/summary.json || ! -f $study/table.txt ]]; then
  echo "error: $study is not a finished study (no summary.json or table.txt); run tools/study.sh" >&2
  exit 1
fi
tools/web_deps.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build/release/collido report "$study" -o "$work/report.html" > /dev/null
# The scene views are linked relative to the study's folder.
if [[ -d $study/views ]]; then ln -s "$(realpath "$study/views")" "$work/views"; fi
COLLIDO_REPORT_HTML="$work/report.html" COLLIDO_TABLE_TXT="$study/table.txt" \
COLLIDO_REPORT_LOAD_LIMIT_MS="$limit" COLLIDO_REPORT_TOP_SCREENSHOT="$screenshot" \
  node --test web/tests/report.test.mjs
