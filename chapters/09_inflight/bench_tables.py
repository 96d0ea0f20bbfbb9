#!/usr/bin/env python3
"""Turns the JSON of ch09_bench (--benchmark_format=json) into chapter 9's Markdown tables. Every
ratio is the single-ray kernel's time over the in-flight kernel's, both measured alternately in
the same benchmark (above 1: rays in flight are faster).

  python3 chapters/09_inflight/bench_tables.py ablation ch09.json  # rays in flight x prefetch
  python3 chapters/09_inflight/bench_tables.py isa ch09.json       # the default, on each ISA
  python3 chapters/09_inflight/bench_tables.py order ch09.json     # a batch sorted against as given
  python3 chapters/09_inflight/bench_tables.py packets ch09.json   # packets against single rays, per ISA
"""
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from gbench_json import runs  # noqa: E402

SCENES = ["bunny", "dragon", "buddha", "sponza", "teapot", "sphere_870k"]
REAL = SCENES[:5]  # the geometric means are over the real meshes
KINDS = ["primary", "diffuse", "shadow"]


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def collect(benchmarks, group):
    """{(scene, kind): {column: benchmark}} for names group/SCENE/KIND/COLUMN."""
    rows = defaultdict(dict)
    for b in benchmarks:
        parts = b["name"].replace("/manual_time", "").split("/")
        if len(parts) >= 4 and parts[0] == group:
            rows[(parts[1], parts[2])][parts[3]] = b
    return rows


def table(rows, columns, first_header, first_cell):
    if not rows:
        sys.exit("bench_tables.py: no benchmarks of that kind in the file")
    print(f"| scene | rays | {first_header} | " + " | ".join(columns) + " |")
    print("|---|---|" + "---:|" * (first_header.count("|") + 1 + len(columns)))
    per_column = defaultdict(list)
    keys = sorted(rows, key=lambda k: (SCENES.index(k[0]) if k[0] in SCENES else 99, KINDS.index(k[1])))
    for key in keys:
        r = rows[key]
        any_b = next(iter(r.values()))
        cells = []
        for c in columns:
            if c in r:
                cells.append(f"{r[c]['speedup']:.2f}")
                if key[0] in REAL:
                    per_column[(key[1], c)].append(r[c]["speedup"])
            else:
                cells.append("-")
        print(f"| {key[0]} | {key[1]} | {first_cell(any_b)} | " + " | ".join(cells) + " |")
    for kind in KINDS:
        if any((kind, c) in per_column for c in columns):
            cells = [f"{geomean(per_column[(kind, c)]):.2f}" if (kind, c) in per_column else "-" for c in columns]
            blanks = "| " * (first_header.count("|") + 1)
            print(f"| **real meshes, geometric mean** | {kind} {blanks}| " + " | ".join(cells) + " |")


def ablation(benchmarks):
    columns = ["r1", "r2", "r4", "r8", "r1-noprefetch", "r2-noprefetch", "r4-noprefetch", "r8-noprefetch"]
    table(collect(benchmarks, "ablation"), columns, "single-ray Mrays/s",
          lambda b: f"{b['single_mrays_per_s']:.2f}")


def isa(benchmarks):
    table(collect(benchmarks, "isa"), ["scalar", "sse4", "avx2", "avx512"], "triangles | tree MB",
          lambda b: f"{int(b['triangles']):,} | {b['tree_mb']:.1f}")


def packets(benchmarks):
    table(collect(benchmarks, "packets"), ["sse4", "avx2", "avx512"], "triangles | tree MB",
          lambda b: f"{int(b['triangles']):,} | {b['tree_mb']:.1f}")


def order(benchmarks):
    """One row per scene, a column per kind of ray: the batch's time as given over its time
    sorted, the sort included, and the sort's share of the sorted time ("as given" where the
    policy leaves the batch unsorted)."""
    rows = defaultdict(dict)
    for b in benchmarks:
        parts = b["name"].replace("/manual_time", "").split("/")
        if len(parts) == 3 and parts[0] == "order":
            rows[parts[1]][parts[2]] = b
    if not rows:
        sys.exit("bench_tables.py: no order benchmarks in the file")
    print("| scene | tree MB | " + " | ".join(f"{k}: sorted / given | {k}: sort's share" for k in KINDS) + " |")
    print("|---|---:|" + "---:|---:|" * len(KINDS))
    for scene in sorted(rows, key=lambda s: SCENES.index(s) if s in SCENES else 99):
        r = rows[scene]
        cells = []
        for k in KINDS:
            if k not in r:
                cells += ["-", "-"]
            elif not r[k]["sorted"]:
                cells += ["as given", "-"]
            else:
                cells += [f"{r[k]['speedup']:.2f}", f"{100 * r[k]['sort_share']:.0f} %"]
        tree = next(iter(r.values()))["tree_mb"]
        print(f"| {scene} | {tree:.1f} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("ablation", "isa", "order", "packets"):
        sys.exit(__doc__)
    {"ablation": ablation, "isa": isa, "order": order, "packets": packets}[sys.argv[1]](runs(sys.argv[2]))
