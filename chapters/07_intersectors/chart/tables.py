"""Chapter 7's tables, from the output of ch07_bench.

    python3 tables.py tests ch07_tests.json               # triangle tests per second
    python3 tables.py chart ch07_speed_vs_accuracy.tsv    # the chart's points, summarised

`tests`: millions of triangle tests per second per intersector at each native width (K = 1
compiled for the best ISA), with the ratio to Möller-Trumbore at the same width; the median of
the repetitions. `chart`: per ray set and ISA, the fastest configuration, the fastest one that
loses no ray, and what that accuracy costs."""
import json
import sys

NAMES = {"moeller": "Möller-Trumbore", "pluecker": "stable Plücker", "watertight": "watertight"}
WIDTHS = [("w1", None, "K = 1"), ("w4", "sse4", "K = 4, SSE4"), ("w8", "avx2", "K = 8, AVX2"),
          ("w16", "avx512", "K = 16, AVX-512")]


def tests(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    medians = [b for b in runs if b.get("aggregate_name") == "median"]
    rate = {}
    for b in medians or runs:
        parts = b.get("run_name", b["name"]).split("/")  # tests/<intersector>/w<K>/<isa>
        if parts[0] == "tests":
            rate[(parts[1], parts[2], parts[3])] = b["Mtests/s"]
    isas = [i for i in ("avx512", "avx2", "sse4", "scalar") if any(k[2] == i for k in rate)]
    pretty = {"scalar": "scalar", "sse4": "SSE4", "avx2": "AVX2", "avx512": "AVX-512"}
    cols = [(w, isa or isas[0], label + (f" ({pretty[isas[0]]} build)" if isa is None else ""))
            for w, isa, label in WIDTHS if (isa or isas[0]) in isas]
    print("| intersector | " + " | ".join(label for _, _, label in cols) + " |")
    print("|---|" + "---:|" * len(cols))
    for kind, name in NAMES.items():
        cells = []
        for w, isa, _ in cols:
            r = rate.get((kind, w, isa))
            base = rate.get(("moeller", w, isa))
            cells.append("-" if r is None else f"{r:.0f}" if kind == "moeller" else f"{r:.0f} ({r / base:.2f})")
        print(f"| {name} | " + " | ".join(cells) + " |")


def chart(path):
    points = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rays, layout, kind, isa, mrays, leaks = line.split("\t")
            points.append((rays, f"{layout}.{kind}", isa, float(mrays), float(leaks)))
    print("| rays | ISA | fastest | its leaks | fastest with no leak | cost of no leak |")
    print("|---|---|---|---:|---|---:|")
    for rays in dict.fromkeys(p[0] for p in points):
        for isa in dict.fromkeys(p[2] for p in points):
            mine = [p for p in points if p[0] == rays and p[2] == isa]
            fast = max(mine, key=lambda p: p[3])
            tight = [p for p in mine if p[4] == 0]
            safe = max(tight, key=lambda p: p[3]) if tight else None
            safe_text = f"`{safe[1]}` {safe[3]:.2f} Mrays/s" if safe else "none"
            cost = f"{(1 - safe[3] / fast[3]) * 100:.0f} %" if safe else "-"
            print(f"| {rays} | {isa} | `{fast[1]}` {fast[3]:.2f} Mrays/s | {fast[4]:.2f} % | {safe_text} | {cost} |")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("tests", "chart"):
        sys.exit("usage: tables.py tests ch07_tests.json | chart ch07_speed_vs_accuracy.tsv")
    {"tests": tests, "chart": chart}[sys.argv[1]](sys.argv[2])
