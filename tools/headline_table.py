#!/usr/bin/env python3
"""Prints the README's headline table from a finished study's summary.json: per scene and query,
the fastest exact setting (with the settings it ties with), its time with the 95% interval, and
the next exact backend family's time over it with that ratio's interval (docs/STUDY.md, "Times and
their intervals"). tools/publish_results.sh puts it between the README's headline markers.

Usage: tools/headline_table.py STUDY_DIR/summary.json
"""
import json
import sys


def interval(low, high, digits):
    return f"[{low:.{digits}f}, {high:.{digits}f}]"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: tools/headline_table.py STUDY_DIR/summary.json")
    path = sys.argv[1]
    try:
        with open(path, encoding="utf-8") as f:
            picks = json.load(f)["what_to_pick"]["picks"]
    except (OSError, ValueError, KeyError) as error:
        sys.exit(f"error: {path}: not a study summary with what_to_pick ({error})")
    print("| scene | query | fastest exact | µs [95% CI] | next exact family | its time over the pick's |")
    print("|---|---|---|---|---|---|")
    for pick in picks:
        best = pick.get("fastest_exact")
        if not best:
            continue
        name = "`" + best["backend"] + "`"
        if best.get("ties"):
            name += " ≈ " + ", ".join("`" + t + "`" for t in best["ties"])
        time = f"{best['mean_us']:.1f} {interval(*best['ci95_us'], 1)}"
        runner = best.get("runner_up")
        if runner:
            ratio = f"{best['runner_up_ratio']:.2f}x {interval(*best['runner_up_ratio_ci95'], 2)}"
            next_family = "`" + runner["backend"] + "`"
        else:
            ratio, next_family = "-", "-"
        print(f"| {pick['scene']} | {pick['query']} | {name} | {time} | {next_family} | {ratio} |")


if __name__ == "__main__":
    main()
