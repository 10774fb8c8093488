#!/usr/bin/env python3
"""Runs bench_vs_vallado (bench/vallado/) and prints trakbox's time per propagation as a ratio of
Vallado's, workload by workload, from the medians of interleaved repetitions in one process.

    python3 scripts/bench_ratios.py build-release/bench/bench_vs_vallado [--repetitions 5]
"""
import argparse
import json
import re
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--filter", default=".")
    args = ap.parse_args()
    out = subprocess.run(
        [args.binary, "--benchmark_format=json", f"--benchmark_repetitions={args.repetitions}",
         "--benchmark_enable_random_interleaving=true", "--benchmark_report_aggregates_only=true",
         f"--benchmark_filter={args.filter}"],
        check=True, capture_output=True, text=True).stdout
    medians = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        # BM_<Kind>_<Workload>_<Impl>[/arg][/min_time...]
        m = re.match(r"BM_(\w+?)_(\w+)_(Vallado|Trakbox)(/\d+)?", b["run_name"])
        if not m:
            continue
        kind, workload, impl, arg = m.group(1), m.group(2), m.group(3), m.group(4) or ""
        medians[(kind, workload + arg, impl)] = (b["per_propagation"] * 1e9, b.get("label", ""))
    print(f"{'workload':46} {'trakbox ns':>11} {'Vallado ns':>11} {'ratio':>6}")
    for (kind, workload, impl), (ns, label) in sorted(medians.items()):
        if impl != "Trakbox":
            continue
        base = medians.get(("PerCall", workload, "Vallado"))
        if not base:
            continue
        name = f"{kind} {workload} ({label})" if label else f"{kind} {workload}"
        print(f"{name:46} {ns:11.1f} {base[0]:11.1f} {ns / base[0]:6.3f}")
    print("(medians of", args.repetitions, "interleaved repetitions; CPU time per propagation; the",
          "batch rows are against Vallado's per-call time on the same sets)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
