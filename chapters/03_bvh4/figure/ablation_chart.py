"""Chapter 3's chart data: what each traversal trick is worth, as the time with the trick off
over the time with all tricks on (geometric mean over the scenes), per node width and ray kind,
from `ch03_bench --benchmark_filter=^ablation/` JSON.

    python3 ablation_chart.py ch03_ablation.json OUT.tsv"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from bench_tables import geomean, load  # noqa: E402


def main():
    ratios, configs, groups = {}, [], []
    for b in load(sys.argv[1]):
        parts = b["name"].split("/")  # ablation/<bvhN-isa>/<scene>/<kind>/<config>
        if parts[0] != "ablation":
            continue
        group, config = f"{parts[1]} {parts[3]}", parts[4]
        configs += [config] if config not in configs else []
        groups += [group] if group not in groups else []
        ratios.setdefault((config, group), []).append(b["vs_all"])
    with open(sys.argv[2], "w") as out:
        out.write("trick off\t" + "\t".join(groups) + "\n")
        for c in configs:
            if c == "all":
                continue  # all tricks against themselves: the method's bias, in the table
            out.write(c.replace("no_", "").replace("_", " ") + "\t" +
                      "\t".join(f"{geomean(ratios.get((c, g), [])):.3f}" for g in groups) + "\n")


if __name__ == "__main__":
    main()
