"""Chapter 11's table of costs, from `ch11_bench` JSON: CPU time per pixel sample of each
sampler, per bin drawn from a table and per camera ray of each camera.

    python3 bench_table.py ch11.json   # Markdown table on standard output"""
import json
import sys

ROWS = [  # benchmark name, what it is
    ("BM_pixel_sample/0", "CPU time per pixel sample of eight 2D points, independent"),
    ("BM_pixel_sample/1", "the same, Sobol (Owen-scrambled, padded)"),
    ("BM_sobol_point/0", "one Sobol 2D point, as defined (sobol_owen_reference)"),
    ("BM_sobol_point/1", "one Sobol 2D point, as the sampler computes it (sobol_owen)"),
    ("BM_discrete_sample/2", "one bin of a table of 2 (a choice of light), random u"),
    ("BM_discrete_sample/16", "one bin of a table of 16"),
    ("BM_discrete_sample/1024", "one bin of a table of 1,024 (an environment map's row)"),
    ("BM_camera_ray/0", "pinhole camera ray"),
    ("BM_camera_ray/10", "thin-lens camera ray"),
]


def main():
    with open(sys.argv[1]) as f:
        runs = {b["name"]: b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"}
    print("| figure | CPU time |")
    print("|---|---:|")
    for name, label in ROWS:
        b = runs[name]
        ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6}[b["time_unit"]]
        extra = ""
        if name == "BM_pixel_sample/1":
            base = runs["BM_pixel_sample/0"]["cpu_time"]
            extra = f" ({b['cpu_time'] / base:.1f}x)"
        if name == "BM_sobol_point/1":
            base = runs["BM_sobol_point/0"]["cpu_time"]
            extra = f" ({base / b['cpu_time']:.1f}x faster)"
        print(f"| {label} | {ns:.3g} ns{extra} |")


if __name__ == "__main__":
    main()
