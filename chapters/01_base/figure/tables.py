"""Chapter 1's tables, from `ch01_bench` JSON: the slab test per variant and width, and the
reciprocals per variant and method.

    python3 tables.py slab ch01_slab.json    # Markdown table on standard output
    python3 tables.py rcp ch01_rcp.json"""
import json
import math
import sys

BACKEND = {  # (variant, width) -> the backend that runs there (simd.h picks it)
    ("scalar", 1): "plain loop", ("sse4", 4): "**SSE4**", ("avx2", 4): "SSE4 header, VEX-encoded",
    ("avx2", 8): "**AVX2**", ("avx512", 4): "SSE4 header, AVX-512VL",
    ("avx512", 8): "AVX2 header, AVX-512VL", ("avx512", 16): "**AVX-512**",
}
NATIVE = {"sse4": 4, "avx2": 8, "avx512": 16}


def rate(x):
    return f"{x / 1e9:.3g} G" if x >= 1e9 else f"{x / 1e6:.3g} M"


def load(path):
    with open(path) as f:
        return [b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"]


def slab(runs):
    print("| variant | width | backend that runs | box tests/s | vs scalar width 1 | vs portable, same width |")
    print("|---|---:|---|---:|---:|---:|")
    for b in runs:
        _, isa, w = b["name"].split("/")
        width = int(w[1:])
        native = NATIVE.get(isa) == width
        speedup = f"{b['vs_scalar1']:.2f}"
        print(f"| {isa} | {width} | {BACKEND.get((isa, width), 'portable')} | {rate(b['items_per_second'])} | "
              f"{'**' + speedup + '**' if native else speedup} | {b['vs_scalar_same_w']:.2f} |")


def rcp(runs):
    print("| variant | width | method | reciprocals/s | vs division | largest relative error |")
    print("|---|---:|---|---:|---:|---:|")
    for b in runs:
        _, isa, w, method = b["name"].split("/")[:4]
        err = b["max_rel_error"]
        print(f"| {isa} | {w[1:]} | {method} | {rate(b['items_per_second'])} | {b['vs_divide']:.2f} | "
              f"{err:.3g} (2^{math.log2(err):.1f}) |")


if __name__ == "__main__":
    {"slab": slab, "rcp": rcp}[sys.argv[1]](load(sys.argv[2]))
