"""Chapter 1's chart data: the slab test's speed-up over the scalar width-1 loop, per ISA
variant (columns) and SIMD width (rows), from `ch01_bench --benchmark_filter=slab` JSON.

    python3 simd_speedups.py ch01_slab.json OUT.tsv"""
import json
import sys

ISAS = ["scalar", "sse4", "avx2", "avx512"]


def main():
    with open(sys.argv[1]) as f:
        runs = json.load(f)["benchmarks"]
    speedup = {}
    for b in runs:
        parts = b["name"].split("/")  # slab/<isa>/w<width>
        if len(parts) == 3 and parts[0] == "slab" and "vs_scalar1" in b:
            speedup[(parts[1], int(parts[2][1:]))] = b["vs_scalar1"]
    isas = [i for i in ISAS if any(k[0] == i for k in speedup)]
    with open(sys.argv[2], "w") as out:
        out.write("width\t" + "\t".join(isas) + "\n")
        for w in (4, 8, 16):
            out.write(f"{w}\t" + "\t".join(f"{speedup.get((i, w), float('nan')):.2f}" for i in isas) + "\n")


if __name__ == "__main__":
    main()
