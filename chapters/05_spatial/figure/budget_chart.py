"""Chapter 5's chart data: the duplication budget of the binned spatial-split builder against
what it makes (references per triangle) and buys (diffuse Mrays/s, relative to the smallest
budget), per scene, from `ch05_bench` JSON (the budget/<scene>/<percent>% benchmarks; the
median of each when the run repeated them).

    python3 budget_chart.py ch05.json OUT.tsv"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from bench_tables import load  # noqa: E402  (chapter 5's table writer, one folder up)


def main():
    # bench_tables.load() picks each benchmark's run (its median where the run repeated them)
    # in the order the benchmark registered them.
    rows, scenes = {}, []
    for name, b in load(sys.argv[1]).items():
        parts = name.split("/")
        if parts[0] != "budget":
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
