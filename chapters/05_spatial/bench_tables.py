#!/usr/bin/env python3
"""Turns the output of ch05_bench and of `rtk trace` into the Markdown tables of chapter 5, one
table at a time, so that the page can place each next to the prose about it.

    ch05_bench --benchmark_out=ch05.json --benchmark_out_format=json
    python3 chapters/05_spatial/bench_tables.py build|trace|bins|budget|overlap|min_leaves ch05.json
    python3 chapters/05_spatial/bench_tables.py rtk TRACE.txt ... [COMPARE.txt]

For `rtk`, each TRACE.txt is the JSON-line output of one `rtk trace` run, named
ch05_trace_<scene>_<rays>_<objectsplit|spatialsplit>.txt; a COMPARE.txt (the output of
`rtk compare`, named ch05_compare_<scene>_<rays>.txt) adds the agreement of the two answers.
"""
import json
import os
import re
import sys


def load(path):
    """Benchmark results by name (without Google Benchmark's /iterations:N and /min_time:T
    suffixes), in the order the benchmark registered them: one iteration run each, or the
    median of the repetitions where the run repeated a benchmark (in random order, with
    --benchmark_enable_random_interleaving)."""
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    repeated = {b["run_name"] for b in runs if b.get("aggregate_name") == "median"}
    chosen = [b for b in runs if b.get("aggregate_name") == "median"] + \
        [b for b in runs if b.get("run_type", "iteration") == "iteration" and b.get("run_name", b["name"]) not in repeated]
    chosen.sort(key=lambda b: (b.get("family_index", 0), b.get("per_family_instance_index", 0)))  # as registered
    return {re.sub(r"(/(iterations|min_time|repeats):[^/]*|/(real|manual)_time)+$", "", b.get("run_name", b["name"])): b
            for b in chosen}


def scenes_of(rows, prefix):
    found = []
    for n in rows:
        m = re.match(prefix + r"/([^/]+)", n)
        if m and m.group(1) not in found:
            found.append(m.group(1))
    return found


def build_table(rows):
    print("| scene | triangles | object Mtris/s | centre: time | refs/tri | SAH | binned: time | refs/tri | SAH |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes_of(rows, "build"):
        b = rows[f"build/{scene}"]
        print(f"| {scene} | {int(b['tris']):,} | {b['object_Mtris/s']:.2f} | {b['centre_time']:.1f}x | "
              f"{b['centre_refs/tri']:.2f} | {b['centre_sah']:.2f} | {b['binned_time']:.1f}x | "
              f"{b['binned_refs/tri']:.2f} | {b['binned_sah']:.2f} |")


def mrays(b):
    return b["items_per_second"] * 1e-6


def trace_table(rows):
    print("| scene | rays | object | centre | binned | binned / object |")
    print("|---|---|---:|---:|---:|---:|")
    for scene in scenes_of(rows, "trace"):
        for kind in ("primary", "diffuse"):
            r = {f: rows.get(f"trace/{scene}/{kind}/{f}") for f in ("object", "centre", "binned")}
            if not all(r.values()):
                continue
            digits = 3 if mrays(r["object"]) < 0.1 else 2
            print(f"| {scene} | {kind} | " + " | ".join(f"{mrays(r[f]):.{digits}f}" for f in r) +
                  f" | {mrays(r['binned']) / mrays(r['object']):.2f} |")


def bins_table(rows):
    scenes = scenes_of(rows, "bins")
    if not scenes:
        return
    print("| bins | " + " | ".join(f"{s} build | {s} refs/tri | {s} SAH" for s in scenes) + " |")
    print("|---:|" + "---:|---:|---:|" * len(scenes))
    counts = sorted({int(n.split("/")[2]) for n in rows if n.startswith("bins/")})
    for bins in counts:
        cells = []
        for s in scenes:
            b = rows[f"bins/{s}/{bins}"]
            cells += [f"{b['cpu_time']:.0f} ms", f"{b['refs/tri']:.3f}", f"{b['sah']:.4g}"]
        print(f"| {bins} | " + " | ".join(cells) + " |")


def budget_table(rows):
    scenes = scenes_of(rows, "budget")
    print("| budget | " + " | ".join(f"{s} refs/tri | {s} Mrays/s" for s in scenes) + " |")
    print("|---:|" + "---:|---:|" * len(scenes))
    budgets = sorted({int(n.split("/")[2].rstrip("%")) for n in rows if n.startswith("budget/")})
    for p in budgets:
        cells = []
        for s in scenes:
            b = rows[f"budget/{s}/{p}%"]
            digits = 3 if mrays(b) < 0.1 else 2
            cells += [f"{b['refs/tri']:.2f}", f"{mrays(b):.{digits}f}"]
        print(f"| {p} % | " + " | ".join(cells) + " |")


def rule_table(rows, prefix, label, value):
    """One row per scene and setting of a pricing rule (`prefix`/scene/setting)."""
    print(f"| scene | {label} | build | build / object's | sets priced | refs/tri | SAH / object's | "
          "diffuse speed / object's |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes_of(rows, prefix):
        settings = sorted({int(n.split("/")[2].rstrip("%")) for n in rows if n.startswith(f"{prefix}/{scene}/")})
        for v in settings:
            b = rows[f"{prefix}/{scene}/{v}" + ("%" if prefix == "overlap" else "")]
            print(f"| {scene} | {value(v)} | {b['build_ms']:.0f} ms | {b['build_time']:.1f}x | {int(b['searches']):,} | "
                  f"{b['refs/tri']:.2f} | {b['sah']:.3f} | {b['diffuse_speed']:.2f} |")


def overlap_table(rows):
    rule_table(rows, "overlap", "min_overlap", lambda p: f"{p / 100:.2f}")


def min_leaves_table(rows):
    rule_table(rows, "min_leaves", "min_leaves", str)


def json_lines(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.startswith("{")]


def rtk_table(paths):
    runs, agreement = {}, {}
    for path in paths:
        name = os.path.basename(path)
        m = re.match(r"ch05_trace_([^_]+)_([^_]+)_(objectsplit|spatialsplit)\.txt$", name)
        c = re.match(r"ch05_compare_([^_]+)_([^_]+)\.txt$", name)
        if m:
            lines = {j["op"]: j for j in json_lines(path)}
            runs[(m.group(1), m.group(2), m.group(3))] = (lines["build"], lines["intersect"])
        elif c:
            agreement[(c.group(1), c.group(2))] = next(j for j in json_lines(path) if j["op"] == "compare")
    print("| scene, rays | objectsplit Mrays/s | spatialsplit Mrays/s | ratio | build s (object, spatial) | "
          "MB (object, spatial) | same answer |")
    print("|---|---:|---:|---:|---|---|---:|")
    for scene, kind in dict.fromkeys((s, k) for s, k, _ in runs):
        o, s = runs.get((scene, kind, "objectsplit")), runs.get((scene, kind, "spatialsplit"))
        if not (o and s):
            continue
        a = agreement.get((scene, kind))
        same = f"{a['agree_percent']:.3f} %" if a else ""
        print(f"| {scene}, {kind} | {o[1]['mrays_per_s']:.2f} | {s[1]['mrays_per_s']:.2f} | "
              f"{s[1]['mrays_per_s'] / o[1]['mrays_per_s']:.2f} | {o[0]['seconds']:.2f}, {s[0]['seconds']:.2f} | "
              f"{o[0]['bytes'] / 1e6:.2f}, {s[0]['bytes'] / 1e6:.2f} | {same} |")


TABLES = {"build": build_table, "trace": trace_table, "bins": bins_table, "budget": budget_table,
          "overlap": overlap_table, "min_leaves": min_leaves_table}


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "rtk":
        rtk_table(sys.argv[2:])
    elif len(sys.argv) == 3 and sys.argv[1] in TABLES:
        TABLES[sys.argv[1]](load(sys.argv[2]))
    else:
        sys.exit("usage: bench_tables.py build|trace|bins|budget|overlap|min_leaves ch05.json, or rtk TRACE.txt ... [COMPARE.txt]")


if __name__ == "__main__":
    main()
