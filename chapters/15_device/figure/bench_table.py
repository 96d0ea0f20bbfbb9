"""Chapter 15's table, from `ch15_bench` JSON (means of the repetitions): a frame through the
device against the same frame through chapter 14's renderer directly, and a scene commit.

    python3 bench_table.py ch15.json   # Markdown table on standard output"""
import json
import sys

ROWS = [("BM_frame_direct", 'frame through \\ref ch14_pathtracer "chapter 14" directly (`BM_frame_direct`)'),
        ("BM_frame_device", "frame through the device (`BM_frame_device`)"),
        ("BM_commit_scene", "scene commit: merge and build (`BM_commit_scene`)")]


def main():
    with open(sys.argv[1]) as f:
        runs = json.load(f)["benchmarks"]
    mean = {}
    for b in runs:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "mean":
            continue
        name = b.get("run_name", b["name"]).split("/")[0]
        mean.setdefault(name, b["real_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1, "s": 1e3}[b["time_unit"]])
    base = mean["BM_frame_direct"]
    print("| | time | ratio |")
    print("|---|---:|---:|")
    for name, label in ROWS:
        ms = mean[name]
        print(f"| {label} | {ms:.3g} ms | {ms / base:.2g} |")


if __name__ == "__main__":
    main()
