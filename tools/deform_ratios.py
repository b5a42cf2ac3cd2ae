#!/usr/bin/env python3
"""Ratios of the deform benchmarks from one collido_bench run (Google Benchmark JSON, medians).

For each deforming scene and query, per backend: update plus query (deform/), the updates alone
(deform_update/), the query after updates (deform_query/) and on freshly built models
(deform_fresh/); then update plus query against FCL OBB's (its time over ours), the update
against Bullet GImpact's, and the query after updates over the query on fresh models.
Usage: tools/deform_ratios.py RUN.json [--reference fcl:obb] [--refit-reference bullet[margin=0]]
"""
import argparse
import json
import re
from collections import OrderedDict

KINDS = ["deform", "deform_update", "deform_query", "deform_fresh"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--reference", default="fcl:obb")
    parser.add_argument("--refit-reference", default="bullet[margin=0]")
    args = parser.parse_args()
    with open(args.run, encoding="utf-8") as f:
        data = json.load(f)
    scenes = OrderedDict()
    for b in data.get("benchmarks", []):
        if b.get("aggregate_name") != "median" or not b["run_name"].startswith("deform"):
            continue
        kind, rest = b["run_name"].split("/", 1)
        match = re.match(r"(.*)/([^/]+)/([^/]+)$", rest)
        if not match or kind not in KINDS:
            continue
        variant, scene, query = match.groups()
        scenes.setdefault((scene, query), OrderedDict()).setdefault(variant, {})[kind] = b[
            "real_time"]
    for (scene, query), variants in scenes.items():
        print(f"== {scene}/{query}")
        reference = variants.get(args.reference, {})
        refit_reference = variants.get(args.refit_reference, {})
        for variant, times in variants.items():
            line = f"  {variant:48s}"
            for kind, label in zip(KINDS, ["update+query", "update", "query", "fresh"]):
                value = times.get(kind)
                line += f" {label}={value:9.1f}" if value is not None else f" {label}=        -"
            if "deform" in times and "deform" in reference:
                line += f"  update+query vs {args.reference} {reference['deform'] / times['deform']:5.2f}x"
            if "deform_update" in times and "deform_update" in refit_reference:
                ratio = refit_reference["deform_update"] / times["deform_update"]
                line += f"  update vs {args.refit_reference} {ratio:5.2f}x"
            if "deform_query" in times and "deform_fresh" in times:
                line += f"  query/fresh {times['deform_query'] / times['deform_fresh']:4.2f}"
            print(line)


if __name__ == "__main__":
    main()
