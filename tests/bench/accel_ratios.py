#!/usr/bin/env python3
"""Ratios of each accelerator to Embree from an accel_bench JSON run.

Reads Google Benchmark JSON (--benchmark_format=json, best with
--benchmark_repetitions=N --benchmark_enable_random_interleaving=true), pairs
each accelerator's repetition i with Embree's repetition i of the same case,
and prints the median of the per-pair throughput ratios (Mrays/s for
queries, Mprims/s for builds) as a Markdown table.

Usage: accel_ratios.py RESULTS.json [YARDSTICK]   (YARDSTICK defaults to 'embree')
"""
import json
import statistics
import sys
from collections import defaultdict


def main():
    path = sys.argv[1]
    yardstick = sys.argv[2] if len(sys.argv) > 2 else "embree"
    runs = json.load(open(path))["benchmarks"]
    # (case, accel) -> {repetition: throughput}
    values = defaultdict(dict)
    for b in runs:
        if b.get("run_type") != "iteration" or not b["name"].startswith("Accel/"):
            continue
        parts = b["name"].replace("/real_time", "").split("/")[1:]
        if parts[0] == "build":
            case, accel, rate = ("build", parts[1], ""), parts[2], b.get("Mprims/s")
        else:
            threads = parts[4] if len(parts) > 4 else "t1"
            case, accel, rate = (parts[0], parts[1], parts[2] + " " + threads), parts[3], b.get("Mrays/s")
        values[(case, accel)][b.get("repetition_index", 0)] = rate
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
                cells.append(f"{median:.2f} ({statistics.median(ratios):.2f}x)" if ratios else f"{median:.2f}")
        print(f"| {case[0]} | {case[1]} | {case[2]} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
