"""Chapter 5's chart data: the duplication budget of the binned spatial-split builder against
what it makes (references per triangle) and buys (diffuse Mrays/s, relative to the smallest
budget), per scene, from `ch05_bench` JSON (the budget/<scene>/<percent>% benchmarks; the
median of each when the run repeated them).

    python3 budget_chart.py ch05.json OUT.tsv"""
import json
import sys


def main():
    with open(sys.argv[1]) as f:
        runs = json.load(f)["benchmarks"]
    # With --benchmark_repetitions, each benchmark's median stands for it.
    medians = any(b.get("aggregate_name") == "median" for b in runs)
    rows, scenes = {}, []
    runs = sorted(runs, key=lambda b: (b.get("family_index", 0), b.get("per_family_instance_index", 0)))
    for b in runs:
        parts = b.get("run_name", b["name"]).split("/")
        kind = "aggregate" if medians else "iteration"
        if parts[0] != "budget" or b.get("run_type", "iteration") != kind:
            continue
        if medians and b.get("aggregate_name") != "median":
            continue
        scene, budget = parts[1], int(parts[2].rstrip("%"))
        scenes += [scene] if scene not in scenes else []
        rows[(scene, budget)] = (b["refs/tri"], b["items_per_second"] * 1e-6)
    budgets = sorted({k[1] for k in rows})
    with open(sys.argv[2], "w") as out:
        out.write("budget\t" + "\t".join(f"{s} refs/tri\t{s} speed" for s in scenes) + "\n")
        for p in budgets:
            cells = []
            for s in scenes:
                refs, mrays = rows.get((s, p), (float("nan"), float("nan")))
                base = rows.get((s, budgets[0]), (0, float("nan")))[1]
                cells += [f"{refs:.3f}", f"{mrays / base:.3f}"]
            out.write(f"{p}\t" + "\t".join(cells) + "\n")


if __name__ == "__main__":
    main()
