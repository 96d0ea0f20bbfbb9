#!/usr/bin/env python3
"""Turns the JSON output of ch04_bench into the Markdown tables of chapter 4, one table at a time,
so that the page can place each next to the prose about it.

    ch04_bench --benchmark_out=ch04.json --benchmark_out_format=json
    python3 chapters/04_sah/bench_tables.py TABLE ch04.json [more.json ...]

TABLE is one of: build (the 1M-triangle terrain), large (the larger terrains), threads, bins, real,
real_bvh8, trace, costs, occluders.
"""
import json
import re
import sys


def load(paths):
    """Benchmark results by name; with --benchmark_repetitions, the median of the repetitions."""
    rows, medians = {}, {}
    for path in paths:
        with open(path) as f:
            for b in json.load(f)["benchmarks"]:
                name = re.sub(r"/(real|manual)_time(_median)?$", "", b.get("run_name", b["name"]))
                if b.get("run_type", "iteration") == "iteration":
                    rows.setdefault(name, b)
                elif b.get("aggregate_name") == "median":
                    medians[name] = b
    rows.update(medians)
    return rows


def scenes_of(rows, prefix):
    """The scenes of the benchmarks named PREFIX<scene>/..., in the order of the run."""
    found = []
    for n in rows:
        m = re.match(re.escape(prefix) + r"([^/]+)/", n)
        if m and m.group(1) not in found:
            found.append(m.group(1))
    return found


def fmt(x, digits=2):
    return f"{x:.{digits}f}"


def build_tables(rows, large=False):
    sizes = sorted({int(m.group(1)) for n in rows for m in [re.match(r"build/bvh\d+/median/tris:(\d+)/", n)] if m})
    for size in sizes:
        if (size > 1000000) != large:
            continue
        print(f"\n**Builds of a {size:,}-triangle terrain** (one thread; SAH priced with Ct = 1, Ci = 0.5; "
              "peak bytes allocated by the build, per triangle):\n")
        print("| tree | builder | Mtris/s | SAH | peak B/tri |")
        print("|---|---|---:|---:|---:|")
        for width in (2, 4, 8):
            for builder in ("median", "binned", "binned+rot"):
                one = rows.get(f"build/bvh{width}/{builder}/tris:{size}/threads:1")
                if one:
                    print(f"| BVH{width} | {builder} | {fmt(one['Mtris'])} | {fmt(one['sah'])} | "
                          f"{fmt(one['peak_B/tri'], 0)} |")


def scaling_table(rows):
    found = []
    for n, b in rows.items():
        m = re.match(r"build/bvh4/(binned|binned\+rot)/tris:(\d+)/threads:1$", n)
        two = rows.get(n.replace("threads:1", "threads:2"))
        if m and two:
            found.append((int(m.group(2)), m.group(1), b, two))
    if not found:
        return
    print("\n**Two threads against one** (BVH4, terrain):\n")
    print("| triangles | builder | Mtris/s, 1 thread | Mtris/s, 2 threads | 2 / 1 | peak MB |")
    print("|---:|---|---:|---:|---:|---:|")
    for size, builder, one, two in sorted(found):
        print(f"| {size:,} | {builder} | {fmt(one['Mtris'])} | {fmt(two['Mtris'])} | "
              f"{fmt(two['Mtris'] / one['Mtris'])} | {fmt(one['peak_MB'], 0)} |")


def bins_table(rows):
    found = sorted((int(m.group(1)), b) for n, b in rows.items() for m in [re.match(r"bins/bvh4/binned/bins:(\d+)/", n)] if m)
    if not found:
        return
    print("\n**Bins per axis** (BVH4, 1M-triangle terrain, 1 thread):\n")
    print("| bins | Mtris/s | SAH |")
    print("|---:|---:|---:|")
    for bins, b in found:
        print(f"| {bins} | {fmt(b['Mtris'])} | {fmt(b['sah'], 3)} |")


def trace_table(rows):
    scenes = scenes_of(rows, "trace/")
    if not scenes:
        return
    print("\n**Tracing through \\ref ch03_bvh4 \"chapter 3\"'s BVH4** (Mrays/s on one thread, best ISA, all tricks; "
          "shadow rays use occluded()):\n")
    print("| scene | SAH median / binned | rays | median | binned | binned+rot | binned / median |")
    print("|---|---:|---|---:|---:|---:|---:|")
    for scene in scenes:
        for kind in ("primary", "diffuse", "shadow"):
            r = {b: rows.get(f"trace/{scene}/{kind}/{b}") for b in ("median", "binned", "binned+rot")}
            if not all(r.values()):
                continue
            sah = f"{fmt(r['median']['sah'], 1)} / {fmt(r['binned']['sah'], 1)}" if kind == "primary" else ""
            print(f"| {scene if kind == 'primary' else ''} | {sah} | {kind} | {fmt(r['median']['Mrays'])} | "
                  f"{fmt(r['binned']['Mrays'])} | {fmt(r['binned+rot']['Mrays'])} | "
                  f"{fmt(r['binned']['Mrays'] / r['median']['Mrays'])} |")


def costs_table(rows):
    found = {}
    for n, b in rows.items():
        m = re.match(r"costs/([^/]+)/([^/]+)/ci:([0-9.]+)$", n)
        if m:
            found.setdefault(m.group(1), {})[(m.group(2), m.group(3))] = b
    if not found:
        return
    costs = ("1", "0.5", "0.25")
    print("\n**Intersection cost** (Ct = 1; BVH4, Mrays/s on one thread; nodes in the tree):\n")
    print("| scene | rays | Ci = 1 | Ci = 0.5 | Ci = 0.25 | nodes: Ci = 1 | 0.5 | 0.25 |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for scene, r in found.items():
        for kind in ("primary", "diffuse"):
            if not all((kind, c) in r for c in costs):
                continue
            rates = " | ".join(fmt(r[(kind, c)]["Mrays"]) for c in costs)
            nodes = " | ".join(f"{int(r[(kind, c)]['nodes']):,}" for c in costs)
            print(f"| {scene if kind == 'primary' else ''} | {kind} | {rates} | {nodes if kind == 'primary' else ' |  | '} |")


def occluder_table(rows):
    scenes = scenes_of(rows, "occluder/")
    if not scenes:
        return
    print("\n**Occluder ordering** (BVH4 with rotations; visits = nodes and leaves a shadow ray enters "
          "before its first hit when children are visited in stored order, as \\ref ch03_bvh4 \"chapter 3\"'s occluded() "
          "visits them; Mrays/s of that occluded()):\n")
    print("| scene | blocked | visits: off | largest_box | likely_blocker | nearest first | "
          "Mrays/s: off | largest_box | likely_blocker |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes:
        r = {o: rows.get(f"occluder/{scene}/{o}") for o in ("off", "largest_box", "likely_blocker")}
        if not all(r.values()):
            continue
        print(f"| {scene} | {fmt(r['off']['blocked'])} | {fmt(r['off']['visits/ray'])} | "
              f"{fmt(r['largest_box']['visits/ray'])} | {fmt(r['likely_blocker']['visits/ray'])} | "
              f"{fmt(r['off']['visits/ray_nearest'])} | {fmt(r['off']['Mrays'])} | "
              f"{fmt(r['largest_box']['Mrays'])} | {fmt(r['likely_blocker']['Mrays'])} |")


def real_table(rows):
    scenes = scenes_of(rows, "real/bvh4/")
    if not scenes:
        return
    print("\n**Builds of real meshes** (BVH4, one thread):\n")
    print("| mesh | Mtris/s: median | binned | binned+rot | SAH: median | binned | binned+rot |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for scene in scenes:
        g = lambda b: rows.get(f"real/bvh4/{scene}/{b}/threads:1")
        med, b1, r1 = g("median"), g("binned"), g("binned+rot")
        if not (med and b1 and r1):
            continue
        print(f"| {scene} | {fmt(med['Mtris'])} | {fmt(b1['Mtris'])} | {fmt(r1['Mtris'])} | "
              f"{fmt(med['sah'], 2)} | {fmt(b1['sah'], 2)} | {fmt(r1['sah'], 2)} |")


def real_bvh8_table(rows):
    scenes = scenes_of(rows, "real/bvh8/")
    if not scenes:
        return
    print("\n**The same for BVH8** (one thread):\n")
    print("| mesh | Mtris/s: binned | binned+rot | rotations' share of the build | SAH: binned | binned+rot |")
    print("|---|---:|---:|---:|---:|---:|")
    for scene in scenes:
        b1 = rows.get(f"real/bvh8/{scene}/binned/threads:1")
        r1 = rows.get(f"real/bvh8/{scene}/binned+rot/threads:1")
        if not (b1 and r1):
            continue
        share = 1 - r1["Mtris"] / b1["Mtris"]
        print(f"| {scene} | {fmt(b1['Mtris'])} | {fmt(r1['Mtris'])} | {share * 100:.0f} % | "
              f"{fmt(b1['sah'], 3)} | {fmt(r1['sah'], 3)} |")


TABLES = {
    "build": build_tables,
    "large": lambda rows: build_tables(rows, large=True),
    "threads": scaling_table,
    "bins": bins_table,
    "real": real_table,
    "real_bvh8": real_bvh8_table,
    "trace": trace_table,
    "costs": costs_table,
    "occluders": occluder_table,
}


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in TABLES:
        sys.exit(f"usage: bench_tables.py {{{'|'.join(TABLES)}}} RESULTS.json [MORE.json ...]")
    TABLES[sys.argv[1]](load(sys.argv[2:]))


if __name__ == "__main__":
    main()
