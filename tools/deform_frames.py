#!/usr/bin/env python3
"""Per-frame table of a deforming scene from a study folder: for each backend setting, the
update cost, the query's median after it and the frame's verdict against the oracle.

Usage: tools/deform_frames.py STUDY_DIR SCENE QUERY SETTING [SETTING ...]
  e.g. tools/deform_frames.py build/release/study deforming_tori all_pairs \\
         'obbtree[max_leaf_triangles=4;float_boxes=false]' fcl:obb 'bullet[margin=0]'

Reads STUDY_DIR/results/*.json (the combinations' full records, declared needs, resolution 1)
and prints a Markdown table: per frame and setting "update µs / query µs", then "r=N" when the
update rebuilt N structures and "✗" when the answer differed from the oracle's; a last row
gives the means, the rebuilds and the wrong frames.
"""
import glob
import json
import os
import sys


def frames_of(study_dir, scene, query, setting):
    for path in glob.glob(os.path.join(study_dir, "results", "*.json")):
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
        c = record["combination"]
        if (c["scene"], c["backend"], c["needs"], c["resolution"], c["limit"]) != (
                scene, setting, "declared", 1.0, 0):
            continue
        for m in record.get("measurements", []):
            if m["query"] == query:
                if m["status"] != "ok":
                    sys.exit(f"{setting} on {scene}/{query}: {m['status']}")
                return m["frames"]
    sys.exit(f"no results for {setting} on {scene}/{query} in {study_dir}")


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    study_dir, scene, query, settings = argv[1], argv[2], argv[3], argv[4:]
    columns = [frames_of(study_dir, scene, query, s) for s in settings]
    print("| frame | " + " | ".join(settings) + " |")
    print("|---|" + "---|" * len(settings))
    for i in range(len(columns[0])):
        cells = []
        for frames in columns:
            f = frames[i]
            cell = f"{f.get('update_us') or 0.0:.0f} / {f['median_us']:.0f}"
            if f.get("update_rebuilds"):
                cell += f" r={f['update_rebuilds']}"
            if f["disagrees"]:
                cell += " ✗"
            cells.append(cell)
        print(f"| {columns[0][i]['frame']} | " + " | ".join(cells) + " |")
    totals = []
    for frames in columns:
        n = len(frames)
        update = sum(f.get("update_us") or 0.0 for f in frames) / n
        query_us = sum(f["median_us"] for f in frames) / n
        rebuilds = sum(f.get("update_rebuilds") or 0 for f in frames)
        wrong = sum(1 for f in frames if f["disagrees"])
        totals.append(f"**{update:.0f} / {query_us:.0f}**, {rebuilds} rebuilds, {wrong} wrong")
    print("| mean | " + " | ".join(totals) + " |")


if __name__ == "__main__":
    main(sys.argv)
