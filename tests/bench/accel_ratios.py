#!/usr/bin/env python3
"""Ratios of each accelerator to Embree from an accel_bench JSON run.

Reads Google Benchmark JSON (--benchmark_format=json, best with
--benchmark_repetitions=N --benchmark_enable_random_interleaving=true), pairs
each accelerator's repetition i with Embree's repetition i of the same case,
and prints the median of the per-pair throughput ratios (Mrays/s for
queries, Mprims/s for builds) as a Markdown table. With four or more
repetitions a cell also gives the ratios' quartiles, "(0.52x, 0.47-0.56)":
on a shared machine one run's ratio can be off by 10-20 %, so a ratio near a
target means something only with its spread. The Accel/paired benchmarks
(an accelerator and Embree taking turns every few milliseconds on the same
rays) get a table of their own.

Usage: accel_ratios.py RESULTS.json [YARDSTICK]   (YARDSTICK defaults to 'embree')
"""
import json
import statistics
import sys
from collections import defaultdict


def ratio_text(ratios):
    """'0.52x', or '0.52x, 0.47-0.56' (median, then lower and upper quartile) from four ratios on."""
    text = f"{statistics.median(ratios):.2f}x"
    if len(ratios) >= 4:
        q1, _, q3 = statistics.quantiles(ratios, n=4)
        text += f", {q1:.2f}-{q3:.2f}"
    return text


def main():
    path = sys.argv[1]
    yardstick = sys.argv[2] if len(sys.argv) > 2 else "embree"
    runs = json.load(open(path))["benchmarks"]
    # (case, accel) -> {repetition: throughput}
    values = defaultdict(dict)
    paired = defaultdict(list)  # (query, scene, accel) -> [(ratio, Mrays/s, yardstick's Mrays/s)]
    for b in runs:
        if b.get("run_type") != "iteration" or not b["name"].startswith("Accel/"):
            continue
        if b["name"].startswith("Accel/paired/"):
            query, scene, _, accel = b["name"].replace("/real_time", "").split("/")[2:6]
            theirs = next((v for k, v in b.items() if k.endswith(" Mrays/s")), 0.0)
            paired[(query, scene, accel)].append((b["ratio"], b["Mrays/s"], theirs))
            continue
        parts = b["name"].replace("/real_time", "").split("/")[1:]
        if parts[0] == "build":
            case, accel, rate = ("build", parts[1], ""), parts[2], b.get("Mprims/s")
        else:
            threads = parts[4] if len(parts) > 4 else "t1"
            case, accel, rate = (parts[0], parts[1], parts[2] + " " + threads), parts[3], b.get("Mrays/s")
        values[(case, accel)][b.get("repetition_index", 0)] = rate
    if values:
        print_separate(values, yardstick)
    if values and paired:
        print()
    if paired:
        print_paired(paired)


def print_separate(values, yardstick):
    """The separate benchmarks: one column per accelerator, ratios to the yardstick's repetition i."""
    cases = sorted({c for c, _ in values})
    accels = sorted({a for _, a in values}, key=lambda a: (a != yardstick, a))
    print("| query | scene | rays | " + " | ".join(accels) + " |")
    print("|---|---|---|" + "---|" * len(accels))
    for case in cases:
        base = values.get((case, yardstick), {})
        cells = []
        for a in accels:
            v = values.get((case, a), {})
            if not v:
                cells.append("")
                continue
            median = statistics.median(v.values())
            unit = "Mprims/s" if case[0] == "build" else "Mrays/s"
            if a == yardstick or not base:
                cells.append(f"{median:.2f} {unit}")
            else:
                ratios = [v[r] / base[r] for r in v if r in base and base[r]]
                cells.append(f"{median:.2f} ({ratio_text(ratios)})" if ratios else f"{median:.2f}")
        print(f"| {case[0]} | {case[1]} | {case[2]} | " + " | ".join(cells) + " |")


def print_paired(paired):
    """The Accel/paired rows: each accelerator and the yardstick taking turns on the same rays."""
    print("| query | scene | accel | paired ratio | Mrays/s | yardstick Mrays/s |")
    print("|---|---|---|---|---|---|")
    for (query, scene, accel), rows in sorted(paired.items()):
        ratios, mine, theirs = zip(*rows)
        print(f"| {query} | {scene} | {accel} | {ratio_text(list(ratios))} | "
              f"{statistics.median(mine):.2f} | {statistics.median(theirs):.2f} |")


if __name__ == "__main__":
    main()
