#!/usr/bin/python3
"""Projects the wall time of a validation suite on a cluster from the case costs measured in
a results directory (DIR/summary.json of `collide validate`). docs/scaling.md explains it.

    scripts/project_scaling.py DIR [--cores 8 64 512] [--scale 1 10] [--top 5]

Model. A case costs what it measured (wall time in advance_to plus the untimed warm-up) plus
a per-case overhead (process start, metrics, writing its files) estimated from the same run:
(suite wall time x slots - sum of measured case times) / cases, where slots = ranks x jobs of
the run (from the summary's "execution" record). Each core runs one case at a time, and
cases are handed out longest first to whichever core is free (what `mpirun collide validate`
does), so the wall time is the makespan of that schedule, simulated here. It can never be
below max(longest case, total / cores). A suite `--scale` times larger has that many copies of
every case (more seeds, scenes, step sizes of the same cost); its longest case stays the same.
"""
import argparse
import heapq
import json
import os
import sys


def load_costs(results_dir):
    with open(os.path.join(results_dir, "summary.json")) as f:
        summary = json.load(f)
    cases = summary["cases"]
    measured = {c["id"]: (c["wall_seconds"] or 0.0) + (c["warmup_seconds"] or 0.0) for c in cases}
    execution = summary.get("execution", {})
    slots = int(execution.get("ranks", 1)) * int(execution.get("jobs_per_rank", 1))
    spare = summary["wall_seconds"] * slots - sum(measured.values())
    overhead = max(0.0, spare / max(len(cases), 1))
    return summary, {k: v + overhead for k, v in measured.items()}, overhead, slots


def makespan(costs, cores):
    """Longest first, each to the core that is free first: the dynamic hand-out's schedule."""
    free_at = [0.0] * cores
    for c in sorted(costs, reverse=True):
        heapq.heappush(free_at, heapq.heappop(free_at) + c)
    return max(free_at)


def split_long(costs, limit):
    """Every case longer than `limit` split into equal pieces of at most `limit` (more seeds,
    each run for a fraction of the duration): the same work, a shorter longest case."""
    out = []
    for c in costs:
        pieces = max(1, int(-(-c // limit))) if limit > 0 else 1
        out += [c / pieces] * pieces
    return out


def fmt(seconds):
    if seconds >= 120:
        return f"{seconds / 60:.1f} min"
    return f"{seconds:.1f} s" if seconds >= 1 else f"{seconds:.2f} s"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results_dir")
    parser.add_argument("--cores", type=int, nargs="+", default=[8, 64, 512])
    parser.add_argument("--scale", type=int, nargs="+", default=[1, 10])
    parser.add_argument("--top", type=int, default=5, help="longest cases to list")
    args = parser.parse_args()
    summary, by_id, overhead, slots = load_costs(args.results_dir)
    costs = list(by_id.values())
    total, longest = sum(costs), max(costs)
    print(f"suite {summary['suite']}: {len(costs)} cases, measured wall {fmt(summary['wall_seconds'])} on "
          f"{slots} slot(s); per-case overhead {overhead:.3f} s; total work {fmt(total)}; longest case {fmt(longest)}\n")
    print("| suite | cores | projected wall | bound max(longest, total/cores) | efficiency | "
          "cases longer than total/cores | with those split |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for scale in args.scale:
        scaled = costs * scale
        for cores in args.cores:
            wall = makespan(scaled, cores)
            bound = max(longest, total * scale / cores)
            split = makespan(split_long(scaled, total * scale / cores), cores)
            efficiency = total * scale / (cores * wall)
            bounding = sum(c > total * scale / cores for c in scaled)
            print(f"| {scale}x | {cores} | {fmt(wall)} | {fmt(bound)} | {efficiency:.0%} | {bounding} | {fmt(split)} |")
    print(f"\nlongest cases (each bounds the wall time from below on enough cores):")
    for case_id, cost in sorted(by_id.items(), key=lambda kv: -kv[1])[:args.top]:
        print(f"  {fmt(cost):>9}  {case_id}")


if __name__ == "__main__":
    sys.exit(main())
