#!/usr/bin/env bash
# tools/publish_results.sh on a study whose sweep named the field table after another family
# ("fcl against the field"): every summary section is found by its key in sections.json and
# published under its own title, and the README's headline is written between its markers, into
# the files --page and --readme name (the repository's own stay untouched).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
study=$work/study
mkdir -p "$study"
echo "0123456789abcdef0123456789abcdef01234567" > "$study/.complete"
cat > "$study/table.txt" <<'TXT'
What to pick (per scene and query):
tori  all_pairs  fcl:obb

Every setting:
(rows)

fcl against the field (single thread, exact answers; per scene and query):
tori  all_pairs  fcl:obb  2.0 us
TXT
python3 - "$study/sections.json" <<'PY'
import json, sys
sections = [
    {"key": "what_to_pick", "title": "What to pick", "heading": "What to pick (per scene and query)",
     "text": "tori  all_pairs  fcl:obb\n"},
    {"key": "field", "title": "fcl against the field",
     "heading": "fcl against the field (single thread, exact answers; per scene and query)",
     "text": "tori  all_pairs  fcl:obb  2.0 us\n\ntori  boolean  fcl:obb  0.5 us\n"},
]
json.dump({"collidoscope_sections": 1, "sections": sections}, open(sys.argv[1], "w"))
PY
echo '{"what_to_pick": {"picks": []}}' > "$study/summary.json"
printf 'Intro\n<!-- headline: written by tools/publish_results.sh; do not edit -->\nold\n<!-- headline end -->\nRest\n' \
  > "$work/README.md"

bash "$repo/tools/publish_results.sh" "$study" --wall 1m00s --page "$work/page.md" \
  --readme "$work/README.md" > "$work/out.txt"

fail() { echo "FAIL: $*" >&2; echo "--- page:" >&2; cat "$work/page.md" >&2; exit 1; }
grep -qx '## What to pick' "$work/page.md" || fail "no What to pick section"
grep -qx '## fcl against the field' "$work/page.md" || fail "the renamed field section was dropped"
# The whole section, its blank line included, not cut at its first empty line.
grep -q 'tori  boolean  fcl:obb  0.5 us' "$work/page.md" || fail "the field section was cut short"
grep -q 'wall time 1m00s' "$work/page.md" || fail "no wall time"
grep -q 'commit 0123456' "$work/README.md" || fail "README headline not written"
grep -qx 'old' "$work/README.md" && fail "README headline not replaced"
grep -qx 'Rest' "$work/README.md" || fail "README text after the markers lost"
echo "ok"
