"""Chapter 12's table of costs, from `ch12_bench` JSON: CPU time per Bsdf::sample call of
each model (BM_bsdf_sample/0..8, in the order of bench_bsdf.cpp's models).

    python3 bench_table.py ch12.json   # Markdown table on standard output"""
import json
import sys

LABELS = ["Lambertian", "SmoothConductor (three Fresnel evaluations, one per channel)",
          "RoughConductor, alpha = 0.2", "SmoothDielectric", "ThinDielectric", "Plastic, smooth coat",
          "Plastic, alpha = 0.2", "Velvet", "MetallicPaint, glitter 0.3, alpha = 0.2"]


def main():
    with open(sys.argv[1]) as f:
        runs = {b["name"]: b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"}
    print("| model | ns per sample |")
    print("|---|---:|")
    for i, label in enumerate(LABELS):
        b = runs[f"BM_bsdf_sample/{i}"]
        ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6}[b["time_unit"]]
        print(f"| {label} | {ns:.3g} |")


if __name__ == "__main__":
    main()
