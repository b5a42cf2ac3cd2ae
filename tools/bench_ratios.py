#!/usr/bin/env python3
"""Ratios from one collido_bench run (Google Benchmark JSON with median aggregates).

For each scene and query: every backend's median time, how many times faster the OBB tree
settings are than each comparator (comparator time / ours, from the same run), the floor ratio
(time / the floor benchmark: one exact triangle test per truly intersecting pair) and the work
per reported pair. With --baseline OLD.json, the change of each median against an older run.
Usage: tools/bench_ratios.py RUN.json [--baseline OLD.json]
"""
import argparse
import json
import sys
from collections import defaultdict


def medians(path):
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    out = {}
    for b in data.get("benchmarks", []):
        if b.get("aggregate_name", "median") != "median" or b.get("error_occurred"):
            continue
        name = b.get("run_name", b["name"])
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b.get("time_unit", "ns")]
        out[name] = {"name": name, "us": b["real_time"] * scale,
                     "box": b.get("box_tests_per_pair"),
                     "tri": b.get("triangle_tests_per_pair"),
                     "bpt": b.get("bytes_per_triangle")}
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run")
    parser.add_argument("--baseline")
    args = parser.parse_args()
    run = medians(args.run)
    base = medians(args.baseline) if args.baseline else {}

    groups = defaultdict(dict)  # (kind, scene/query) -> backend -> figures
    for name, fig in run.items():
        parts = name.split("/")
        if parts[0] == "floor" and len(parts) == 3:
            groups[("floor", parts[1] + "/" + parts[2])]["floor"] = fig
        elif parts[0] in ("query", "build") and len(parts) == 4:
            groups[(parts[0], parts[2] + "/" + parts[3])][parts[1]] = fig
        elif parts[0] == "scaling" and len(parts) == 4:
            groups[("query", "spheres_100k/" + parts[2])][parts[1]] = fig
    comparators = ["fcl:obb", "fcl:obbrss", "bullet", "ode"]
    for (kind, what), backends in sorted(groups.items()):
        if kind == "floor":
            continue
        floor = groups.get(("floor", what), {}).get("floor")
        print(f"\n== {kind} {what}" + (f"  (floor {floor['us']:.1f} us)" if floor else ""))
        for backend, fig in sorted(backends.items()):
            line = f"  {backend:48s} {fig['us']:10.1f} us"
            if kind == "build" and fig["bpt"]:
                line += f"  {fig['bpt']:6.1f} B/tri"
            if backend.startswith("obbtree"):
                for c in comparators:
                    if c in backends:
                        line += f"  {backends[c]['us'] / fig['us']:5.2f}x {c}"
            if floor and kind == "query" and what.endswith("all_pairs"):
                line += f"  floor ratio {fig['us'] / floor['us']:5.1f}"
            if fig.get("box") and kind == "query" and what.endswith("all_pairs"):
                line += f"  {fig['box']:.1f} box + {fig['tri']:.2f} tri tests/pair"
            old = base.get(fig["name"])
            if old:
                line += f"  (baseline {old['us']:.1f} us: {old['us'] / fig['us']:.2f}x)"
            print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
