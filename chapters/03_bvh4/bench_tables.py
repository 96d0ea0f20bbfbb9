#!/usr/bin/env python3
"""Turns the JSON of ch02_bench / ch03_bench (--benchmark_format=json) into the Markdown tables
of chapters 2 and 3. Every ratio in a table comes from one run of one program.

  python3 chapters/03_bvh4/bench_tables.py isa    ch02.json   # BVH2: each ISA against scalar
  python3 chapters/03_bvh4/bench_tables.py widths ch03.json   # BVH2/4/8/16 per ISA
  python3 chapters/03_bvh4/bench_tables.py hits ch03.json     # nodes per ray, children hit
  python3 chapters/03_bvh4/bench_tables.py ablation ch03.json # each trick off against all on
"""
import json
import math
import sys
from collections import defaultdict


def load(path):
    """The benchmarks of a run; with --benchmark_repetitions, their medians."""
    with open(path) as f:
        benchmarks = json.load(f)["benchmarks"]
    if any(b.get("run_type") == "aggregate" for b in benchmarks):
        benchmarks = [dict(b, name=b["run_name"]) for b in benchmarks if b.get("aggregate_name") == "median"]
    for b in benchmarks:
        b["name"] = b["name"].replace("/manual_time", "")
    return benchmarks


def rate(b):
    """Mrays/s of a benchmark, from its own counter when the ablation reports one."""
    return b.get("mrays_per_s", b.get("items_per_second", 0) / 1e6)


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def isa_table(benchmarks):
    # bvh2/<scene>/<kind>/<op>/<isa>
    rows = defaultdict(dict)
    for b in benchmarks:
        accel, scene, kind, op, isa = b["name"].split("/")[:5]
        if op == "intersect":
            rows[(scene, kind)][isa] = rate(b)
    isas = ["scalar", "sse4", "avx2", "avx512"]
    print("| scene | rays | scalar Mrays/s | " + " | ".join(f"{i} / scalar" for i in isas[1:]) + " |")
    print("|---|---|---:|" + "---:|" * (len(isas) - 1))
    for (scene, kind), r in rows.items():
        cells = [f"{r[i] / r['scalar']:.2f}" if i in r else "-" for i in isas[1:]]
        print(f"| {scene} | {kind} | {r['scalar']:.2f} | " + " | ".join(cells) + " |")


def widths_table(benchmarks):
    # bvhN/<scene>/<kind>/intersect/<isa>; the statistics are the same for every ISA (tested)
    rows = defaultdict(dict)
    for b in benchmarks:
        parts = b["name"].split("/")
        if not parts[0].startswith("bvh") or parts[3] != "intersect":
            continue
        rows[(parts[1], parts[2])][f"{parts[0]}-{parts[4]}"] = rate(b)
    columns = ["bvh2-sse4", "bvh4-sse4", "bvh4-avx2", "bvh8-avx2", "bvh8-avx512", "bvh16-avx512"]
    print("| scene | rays | bvh4-scalar Mrays/s | " + " | ".join(columns) + " |")
    print("|---|---|---:|" + "---:|" * len(columns))
    for (scene, kind), r in rows.items():
        base = r.get("bvh4-scalar")
        cells = [f"{r[c] / base:.2f}" if c in r and base else "-" for c in columns]
        print(f"| {scene} | {kind} | {base:.2f} | " + " | ".join(cells) + " |")


def hits_table(benchmarks):
    # The statistics of bvhN/<scene>/<kind>/intersect/<isa>, the same for every ISA (tested).
    stats = defaultdict(dict)
    for b in benchmarks:
        parts = b["name"].split("/")
        if not parts[0].startswith("bvh") or parts[3] != "intersect":
            continue
        if "nodes_per_ray" in b and parts[0] not in stats[(parts[1], parts[2])]:
            stats[(parts[1], parts[2])][parts[0]] = b
    print("| scene | rays | BVH4 nodes/ray | BVH4 0-2 hit | BVH8 nodes/ray | BVH8 0-2 hit | BVH16 nodes/ray | BVH16 0-2 hit |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for (scene, kind), s in stats.items():
        cells = []
        for w in ["bvh4", "bvh8", "bvh16"]:
            if w in s:
                cells += [f"{s[w]['nodes_per_ray']:.1f}", f"{100 * s[w]['hit0-2']:.0f}%"]
            else:
                cells += ["-", "-"]
        print(f"| {scene} | {kind} | " + " | ".join(cells) + " |")


def ablation_table(benchmarks):
    # ablation/<bvhN-isa>/<scene>/<kind>/<config>
    ratios = defaultdict(list)
    configs, groups = [], []
    for b in benchmarks:
        parts = b["name"].split("/")
        if parts[0] != "ablation":
            continue
        group = f"{parts[1]} {parts[3]}"
        config = parts[4]
        if config not in configs:
            configs.append(config)
        if group not in groups:
            groups.append(group)
        ratios[(config, group)].append(b["vs_all"])
    print("| trick off | " + " | ".join(groups) + " |")
    print("|---|" + "---:|" * len(groups))
    for config in configs:
        cells = [f"{geomean(ratios[(config, g)]):.3f}" for g in groups]
        print(f"| {config} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    tables = {"isa": isa_table, "widths": widths_table, "hits": hits_table, "ablation": ablation_table}
    if len(sys.argv) != 3 or sys.argv[1] not in tables:
        sys.exit(__doc__)
    tables[sys.argv[1]](load(sys.argv[2]))
