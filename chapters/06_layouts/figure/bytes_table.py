"""Chapter 6's memory table, from `ch06_bench` JSON: bytes per triangle (nodes, leaf blocks and
the shared vertices of the indexed layouts) of every layout, per scene and node width. The
figure does not depend on the ISA; the run measures one.

    python3 bytes_table.py ch06_bytes.json   # Markdown table on standard output"""
import json
import sys

LAYOUTS = ["triangle1", "triangle4", "triangle8", "triangle1i", "triangle4i", "triangle1v", "triangle4v"]


def main():
    with open(sys.argv[1]) as f:
        runs = [b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    size, scenes = {}, []
    for b in runs:
        parts = b["name"].split("/")  # layouts/<scene>/<kind>/bvh<N>/<layout.isect>/<isa>
        if parts[0] != "layouts" or len(parts) < 6:
            continue
        scene, width, layout = parts[1], parts[3], parts[4].split(".")[0]
        scenes += [scene] if scene not in scenes else []
        size[(scene, width, layout)] = b["bytes/tri"]
    cols = [(s, w) for s in scenes for w in ("bvh2", "bvh4", "bvh8")]
    print("| layout | " + " | ".join(f"{s}, {w.upper()}" for s, w in cols) + " |")
    print("|---|" + "---:|" * len(cols))
    for layout in LAYOUTS:
        cells = [f"{size[(s, w, layout)]:.1f}" if (s, w, layout) in size else "-" for s, w in cols]
        print(f"| `{layout}` | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
