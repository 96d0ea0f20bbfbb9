"""Chapter 6's speed table, from `ch06_bench` JSON (medians when the run repeated): Mrays/s of
every layout with Möller-Trumbore, primary and diffuse rays, per ISA.

    python3 speed_table.py ch06_speed.json   # Markdown table on standard output"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "scripts"))
import gbench_json  # noqa: E402

LAYOUTS = ["triangle1", "triangle4", "triangle8", "triangle1i", "triangle4i", "triangle1v", "triangle4v"]
ISAS = [("scalar", "scalar"), ("sse4", "SSE4"), ("avx2", "AVX2"), ("avx512", "AVX-512")]


def main():
    runs = gbench_json.runs(sys.argv[1])
    rate = {}
    for b in runs:
        parts = b["name"].split("/")  # layouts/<scene>/<kind>/bvh4/<layout.isect>/<isa>
        if parts[0] == "layouts" and len(parts) >= 6 and parts[4].endswith(".moeller"):
            rate[(parts[2], parts[4].removesuffix(".moeller"), parts[5])] = b["Mrays/s"]
    isas = [(i, n) for i, n in ISAS if any(k[2] == i for k in rate)]
    cols = [(kind, i, n) for kind in ("primary", "diffuse") for i, n in isas]
    print("| layout | " + " | ".join(f"{kind}, {n}" for kind, _, n in cols) + " |")
    print("|---|" + "---:|" * len(cols))
    for layout in LAYOUTS:
        cells = [f"{rate[(kind, layout, i)]:.2f}" if (kind, layout, i) in rate else "-" for kind, i, _ in cols]
        print(f"| `{layout}` | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
