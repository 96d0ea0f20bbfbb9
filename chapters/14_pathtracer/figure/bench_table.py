"""Chapter 14's table, from `bench_render` JSON: the path tracer's samples and rays per second
and the share of its time in ray queries, on the Cornell box with each ISA's default kernels
with each sampler, and on the Stanford bunny and the Happy Buddha.

    python3 bench_table.py ch14.json   # Markdown table on standard output"""
import json
import sys


def main():
    with open(sys.argv[1]) as f:
        runs = [b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    print("| scene, kernels | threads | samples/s | Mrays/s | rays per sample | time in ray queries |")
    print("|---|---:|---:|---:|---:|---:|")
    for b in runs:
        if b.get("error_occurred"):
            continue
        name = b["name"]
        scene = ("Cornell box, independent samples" if name.startswith("BM_cornell_box_sampler/sampler:0") else
                 "Cornell box, Sobol samples" if name.startswith("BM_cornell_box_sampler/sampler:1") else
                 "Cornell box" if name.startswith("BM_cornell_box") else
                 "bunny" if name.startswith("BM_bunny") else
                 "Happy Buddha" if name.startswith("BM_buddha") else name)
        threads = name.split("threads:")[1].split("/")[0] if "threads:" in name else "1"
        print(f"| {scene}, {b.get('label', '')} | {threads} | {b['items_per_second'] / 1e3:.1f} k | "
              f"{b['Mrays/s']:.3f} | {b['rays/sample']:.2f} | {100 * b['kernel_share']:.0f} % |")


if __name__ == "__main__":
    main()
