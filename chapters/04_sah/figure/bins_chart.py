"""Chapter 4's chart data: the number of SAH bins against build speed and tree quality (the SAH
cost of the finished tree), both relative to 32 bins, from the bins/ benchmarks of `ch04_bench`
(JSON; medians when the run repeated).

    python3 bins_chart.py ch04_bins.json OUT.tsv"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "scripts"))
import gbench_json  # noqa: E402


def main():
    runs = gbench_json.runs(sys.argv[1])
    rows = {}
    for b in runs:
        m = re.match(r"bins/[^/]+/[^/]+/bins:(\d+)/", b["name"])
        if m:
            rows[int(m.group(1))] = (b["Mtris"], b["sah"])
    base = rows[32]
    with open(sys.argv[2], "w") as out:
        out.write("bins\tbuild speed\tSAH cost\tMtris/s\tSAH\n")
        for bins in sorted(rows):
            mtris, sah = rows[bins]
            out.write(f"{bins}\t{mtris / base[0]:.4f}\t{sah / base[1]:.5f}\t{mtris:.3f}\t{sah:.4f}\n")


if __name__ == "__main__":
    main()
