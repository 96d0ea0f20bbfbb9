#!/usr/bin/env python3
"""The summaries of the Embree comparison page, from the JSON that make_table.sh and
bench_render_kernels write (scripts/measure.sh embree runs all three):

    python3 bench/embree/summary.py standing results.json results_sse4.json
    python3 bench/embree/summary.py build results.json
    python3 bench/embree/summary.py render embree_render.json
    python3 bench/embree/summary.py threads embree_build_*.json
    python3 bench/embree/summary.py scaling embree_scaling_*.json

`standing` gives, per RTK configuration and kind of ray, the range and median over the real
meshes of RTK's speed as a ratio to Embree's in the same run; `build` the same for build speed
and memory; `render` the renderer on both sets of kernels; `threads` RTK's default build
against Embree's per scene on one and on two threads (runs of bench_embree --builds-only, one
or more per thread count and scene size); `scaling` what the second thread gives each builder,
measured in pairs (runs of bench_embree --scaling).
"""
import json
import re
import statistics
import sys

# The procedural scenes; every other scene of the run is a real mesh.
PROCEDURAL = {"sphere", "soup", "terrain", "slivers"}
ISA_NAMES = {"scalar": "scalar", "sse4": "SSE4", "avx2": "AVX2", "avx512": "AVX-512"}


def benchmarks(path):
    with open(path) as f:
        data = json.load(f)
    return data, [b for b in data["benchmarks"] if b.get("run_type", "iteration") == "iteration"]


def spread(values, digits=2):
    if not values:
        return "–"
    return f"{min(values):.{digits}f}-{max(values):.{digits}f}, median {statistics.median(values):.{digits}f}"


def describe(tracer):
    """rtk:avx512:bvh8.objectsplit:triangle8.moeller -> 'AVX-512, BVH8, triangle8' (+ spatial splits,
    + every batch as given for a name ending in :given)."""
    _, isa, accel, tri, *given = tracer.split(":")
    structure, split = accel.split(".")
    text = f"{ISA_NAMES.get(isa, isa)}, {structure.upper()}, {tri.split('.')[0]}"
    text += ", spatial splits" if split == "spatialsplit" else ""
    return text + (", every batch as given" if given else "")


def trace_ratios(path):
    """{tracer: {kind: [ratios over the real meshes]}} and Embree's ISA, in the file's order."""
    data, runs = benchmarks(path)
    ratios = {}
    for b in runs:
        m = re.match(r"trace/([^/]+)/([^/]+)/(rtk:[^/]+)/", b["name"])
        if m and m.group(1) not in PROCEDURAL:
            ratios.setdefault(m.group(3), {}).setdefault(m.group(2), []).append(b["rtk_vs_embree"])
    return ratios, data["context"].get("embree", "")


def order_gains(path):
    """{kind: [Embree's speed in RTK's order / as given, over the real meshes]}."""
    _, runs = benchmarks(path)
    gains = {}
    for b in runs:
        m = re.match(r"trace/([^/]+)/([^/]+)/embree:rtk-order/", b["name"])
        if m and m.group(1) not in PROCEDURAL:
            gains.setdefault(m.group(2), []).append(b["order_gain"])
    return gains


def standing(paths):
    print("| RTK's kernels | against Embree's | primary | diffuse | shadow |")
    print("|---|---|---:|---:|---:|")
    for n, path in enumerate(paths):
        ratios, _ = trace_ratios(path)
        against = "best ISA" if n == 0 else "SSE4.2 only"
        for tracer, kinds in ratios.items():
            cells = " | ".join(spread(kinds.get(k, [])) for k in ("primary", "diffuse", "shadow"))
            print(f"| {describe(tracer)} | {against} | {cells} |")
        gains = order_gains(path)
        if gains:
            cells = " | ".join(spread(gains.get(k, [])) for k in ("primary", "diffuse", "shadow"))
            print(f"| (not RTK) Embree's own speed on the rays in RTK's order, over as given | {against} | {cells} |")


def build(path):
    _, runs = benchmarks(path)
    embree, rtk = {}, {}
    for b in runs:
        m = re.match(r"build/([^/]+)/([^/]+)/", b["name"])
        if not m or m.group(1) in PROCEDURAL:
            continue
        if m.group(2) == "embree":
            embree[m.group(1)] = b
        else:
            rtk.setdefault(m.group(2), {})[m.group(1)] = b
    print("| RTK's structure | build speed / Embree's | RTK bytes/tri | Embree bytes/tri |")
    print("|---|---:|---:|---:|")
    for tracer, scenes in rtk.items():
        if "spatialsplit" in tracer:
            continue
        speed = [b["rtk_vs_embree"] for b in scenes.values()]  # measured in pairs
        mine = [b["bytes_per_tri"] for b in scenes.values()]
        theirs = [embree[s]["bytes_per_tri"] for s in scenes if s in embree]
        _, accel, tri = tracer.split(":")
        print(f"| {accel.split('.')[0].upper()}, {tri.split('.')[0]} | {spread(speed)} | "
              f"{min(mine):.0f}-{max(mine):.0f} | {min(theirs):.0f}-{max(theirs):.0f} |")


def threads(paths):
    """One row per scene (a terrain per size): the paired build ratio on each thread count (the
    range over the runs), what the second thread gives each builder (from the mean rates), and
    the bytes per triangle of both."""
    rows = {}  # (scene, triangles) -> {threads: [benchmark of each run]}
    for path in paths:
        data, runs = benchmarks(path)
        t = int(data["context"]["build_threads"])
        for b in runs:
            m = re.match(r"build/([^/]+)/rtk:", b["name"])
            if m:
                rows.setdefault((m.group(1), int(b["triangles"])), {}).setdefault(t, []).append(b)
    counts = sorted({t for row in rows.values() for t in row})
    if counts != [1, 2]:
        sys.exit(f"summary.py threads: runs on 1 and 2 threads wanted, got {counts}")

    def ratios(runs):
        low, high = min(b["rtk_vs_embree"] for b in runs), max(b["rtk_vs_embree"] for b in runs)
        return f"{low:.2f}" if f"{low:.2f}" == f"{high:.2f}" else f"{low:.2f}-{high:.2f}"

    def mean(values):
        return sum(values) / len(values)

    print("| scene | triangles | RTK / Embree, 1 thread | RTK / Embree, 2 threads | "
          "2 threads / 1: RTK | Embree | bytes/tri: RTK | Embree |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    # The real meshes first, then the generated scenes by size.
    for scene, tris in sorted(rows, key=lambda k: (k[0] in PROCEDURAL, k[1] if k[0] in PROCEDURAL else 0)):
        one, two = rows[(scene, tris)].get(1), rows[(scene, tris)].get(2)
        if not one or not two:
            continue
        # Embree's rate in a pair: RTK's rate over the ratio (both from the same iterations).
        rtk_rate = {t: mean([b["Mtris_per_s"] for b in runs]) for t, runs in ((1, one), (2, two))}
        embree_rate = {t: mean([b["Mtris_per_s"] / b["rtk_vs_embree"] for b in runs])
                       for t, runs in ((1, one), (2, two))}
        name = f"{scene} (generated)" if scene in PROCEDURAL else scene
        print(f"| {name} | {tris:,} | {ratios(one)} | {ratios(two)} | "
              f"{rtk_rate[2] / rtk_rate[1]:.2f} | {embree_rate[2] / embree_rate[1]:.2f} | "
              f"{one[0]['bytes_per_tri']:.0f} | {mean([b['embree_bytes_per_tri'] for b in one]):.0f} |")


def scaling(paths):
    """One row per scene (a terrain per size): each builder's gain from the threads, its one- and
    many-thread builds timed back to back in every iteration (the range over the runs)."""
    rows = {}  # (scene, triangles) -> [benchmark of each run]
    threads = set()
    for path in paths:
        _, runs = benchmarks(path)
        for b in runs:
            m = re.match(r"scaling/([^/]+)/rtk:", b["name"])
            if m:
                rows.setdefault((m.group(1), int(b["triangles"])), []).append(b)
                threads.add(int(b["threads"]))
    if len(threads) != 1:
        sys.exit(f"summary.py scaling: runs on one thread count wanted, got {sorted(threads)}")
    t = threads.pop()

    def span(runs, key):
        low, high = min(b[key] for b in runs), max(b[key] for b in runs)
        return f"{low:.2f}" if f"{low:.2f}" == f"{high:.2f}" else f"{low:.2f}-{high:.2f}"

    print(f"| scene | triangles | {t} threads / 1: RTK | Embree | RTK / Embree, {t} threads | runs |")
    print("|---|---:|---:|---:|---:|---:|")
    for scene, tris in sorted(rows, key=lambda k: (k[0] in PROCEDURAL, k[1] if k[0] in PROCEDURAL else 0)):
        runs = rows[(scene, tris)]
        name = f"{scene} (generated)" if scene in PROCEDURAL else scene
        print(f"| {name} | {tris:,} | {span(runs, 'rtk_scaling')} | {span(runs, 'embree_scaling')} | "
              f"{span(runs, 'rtk_vs_embree')} | {len(runs)} |")


def render(path):
    _, runs = benchmarks(path)
    scenes = {"cornell": "Cornell box", "mesh:0": "Stanford bunny", "mesh:1": "Sponza"}
    print("| scene | kernels | samples/s | Mrays/s | time in the kernels | kernels alone, Mrays/s |")
    print("|---|---|---:|---:|---:|---:|")
    for b in runs:
        name = b["name"]
        scene = next((v for k, v in scenes.items() if k in name), name.split("/")[0])
        label = b.get("label", "").removeprefix("rtk ")
        kernels = "Embree 3" if "kernels:1" in name else f"RTK ({label})"
        print(f"| {scene} | {kernels} | {b['items_per_second'] / 1e3:,.0f} k | {b['Mrays/s']:.2f} | "
              f"{b['kernel_share'] * 100:.0f} % | {b['kernel_Mrays/s']:.2f} |")


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "standing":
        standing(sys.argv[2:])
    elif len(sys.argv) == 3 and sys.argv[1] in ("build", "render"):
        {"build": build, "render": render}[sys.argv[1]](sys.argv[2])
    elif len(sys.argv) >= 4 and sys.argv[1] == "threads":
        threads(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "scaling":
        scaling(sys.argv[2:])
    else:
        sys.exit("usage: summary.py standing RESULTS.json [SSE4.json] | build RESULTS.json | "
                 "render RENDER.json | threads BUILDS.json... | scaling SCALING.json...")


if __name__ == "__main__":
    main()
