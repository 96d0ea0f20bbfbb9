#!/usr/bin/env python3
"""Turns the JSON output of ch08_bench into the Markdown tables of chapter 8, one table at a time.

    ch08_bench --benchmark_out=ch08.json --benchmark_out_format=json
    python3 chapters/08_motion/bench_tables.py static|motion|wide|storage ch08.json

Every benchmark is a pair A_vs_B traced in turn; the tables give the ratio B/A of rays per
second (each side's best iteration) and the bytes per triangle of both structures.
"""
import json
import sys

ISAS = ("scalar", "sse4", "avx2", "avx512")
ISA_NAMES = {"scalar": "scalar", "sse4": "SSE4", "avx2": "AVX2", "avx512": "AVX-512"}


def load(path):
    """Pairs by (rays, A, B) and ISA."""
    pairs = {}
    with open(path) as f:
        for b in json.load(f)["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration":
                continue
            _, rays, contenders, isa = b["name"].split("/")[:4]
            a, bee = contenders.split("_vs_")
            pairs.setdefault((rays, a, bee), {})[isa] = b
    return pairs


def isas_in(pairs, key):
    return [i for i in ISAS if i in pairs.get(key, {})]


def ratio_rows(pairs, a, b, label=None):
    """Rows of B/A per ISA for primary and diffuse rays."""
    isas = isas_in(pairs, ("primary", a, b))
    for rays in ("primary", "diffuse"):
        r = pairs[(rays, a, b)]
        lead = f"| {label} | {rays} |" if label is not None else f"| {rays} |"
        yield lead + "".join(f" {r[i]['B/A']:.2f} |" for i in isas), r


def static_table(pairs):
    a, b = "static.bvh4", "static.bvh4mb.sparse"
    isas = isas_in(pairs, ("primary", a, b))
    print("| rays | " + " | ".join(ISA_NAMES[i] for i in isas) + " | bytes/tri BVH4 | bytes/tri BVH4MB |")
    print("|---|" + "---:|" * (len(isas) + 2))
    for line, r in ratio_rows(pairs, a, b):
        any_isa = r[isas[0]]
        print(f"{line} {any_isa['A_bytes/tri']:.1f} | {any_isa['B_bytes/tri']:.1f} |")


def motion_table(pairs):
    a = "static.bvh4mb.sparse"
    isas = isas_in(pairs, ("primary", a, "move1.bvh4mb.sparse"))
    print("| B | rays | " + " | ".join(ISA_NAMES[i] for i in isas) + " |")
    print("|---|---|" + "---:|" * len(isas))
    labels = {"move1": "`move1`: 1 %, all one way", "move30": "`move30`: 30 %, all one way",
              "cross30": "`cross30`: 30 %, rows crossing"}
    for scene, label in labels.items():
        for n, (line, _) in enumerate(ratio_rows(pairs, a, f"{scene}.bvh4mb.sparse", label)):
            print(line if n == 0 else line.replace(f"| {label} |", "| |", 1))


def wide_table(pairs):
    isas = isas_in(pairs, ("primary", "static.bvh4mb.sparse", "static.bvh8mb.sparse"))
    print("| scene | rays | " + " | ".join(ISA_NAMES[i] for i in isas) + " | bytes/tri BVH4MB | bytes/tri BVH8MB |")
    print("|---|---|" + "---:|" * (len(isas) + 2))
    for scene in ("static", "move30"):
        for line, r in ratio_rows(pairs, f"{scene}.bvh4mb.sparse", f"{scene}.bvh8mb.sparse",
                                  scene if scene == "static" else f"`{scene}`"):
            any_isa = r[isas[0]]
            print(f"{line} {any_isa['A_bytes/tri']:.1f} | {any_isa['B_bytes/tri']:.1f} |")


def storage_table(pairs):
    a, b = "tenth.bvh4mb.dense", "tenth.bvh4mb.sparse"
    isas = isas_in(pairs, ("primary", a, b))
    print("| rays | " + " | ".join(ISA_NAMES[i] for i in isas) + " |")
    print("|---|" + "---:|" * len(isas))
    for line, _ in ratio_rows(pairs, a, b):
        print(line)
    r = pairs[("primary", a, b)][isas[0]]
    print("\n| storage | vertex bytes/tri | all bytes/tri |")
    print("|---|---:|---:|")
    print(f"| dense | {r['A_vtx_bytes/tri']:.2f} | {r['A_bytes/tri']:.2f} |")
    print(f"| sparse | {r['B_vtx_bytes/tri']:.2f} | {r['B_bytes/tri']:.2f} |")


TABLES = {"static": static_table, "motion": motion_table, "wide": wide_table, "storage": storage_table}


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in TABLES:
        sys.exit(f"usage: bench_tables.py {'|'.join(TABLES)} ch08.json")
    TABLES[sys.argv[1]](load(sys.argv[2]))


if __name__ == "__main__":
    main()
