"""Chapter 6's chart data: bytes per triangle against Mrays/s for every layout with
Möller-Trumbore (chapter 7 compares the intersectors) on the best ISA of the run, primary and diffuse rays, from `ch06_bench` JSON (medians when the
run repeated). Each row also carries where its label goes, nudged so that labels of nearby
points do not overlap.

    python3 bytes_speed.py ch06_speed.json OUT.tsv"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "scripts"))
import gbench_json  # noqa: E402

ISAS = ["avx512", "avx2", "sse4", "scalar"]


def main():
    runs = gbench_json.runs(sys.argv[1])
    points = {}
    for b in runs:
        parts = b["name"].split("/")  # layouts/<scene>/<kind>/bvh<N>/<layout.isect>/<isa>
        if parts[0] != "layouts" or len(parts) < 6 or not parts[4].endswith(".moeller"):
            continue
        points[(parts[2], parts[4], parts[5])] = (b["bytes/tri"], b["Mrays/s"])
    isa = next(i for i in ISAS if any(k[2] == i for k in points))
    with open(sys.argv[2], "w") as out:
        out.write("kind\tlayout\tbytes/tri\tMrays/s\tlabel_x\tlabel_y\n")
        for kind in ("primary", "diffuse"):
            rows = sorted((v[1], v[0], k[1]) for k, v in points.items() if k[0] == kind and k[2] == isa)
            if not rows:
                continue
            span = (rows[-1][0] - rows[0][0]) or 1.0
            placed = []
            for mrays, bytes_, layout in rows:
                y = mrays
                # Move up until no label already placed is both near in x and in y.
                while any(abs(y - py) < 0.045 * span and abs(bytes_ - px) < 14 for px, py in placed):
                    y += 0.02 * span
                placed.append((bytes_, y))
                out.write(f"{kind}\t{layout.removesuffix('.moeller')}\t{bytes_:.1f}\t{mrays:.3f}\t{bytes_ + 1.2:.1f}\t{y:.3f}\n")
        out.write(f"# isa\t{isa}\n")


if __name__ == "__main__":
    main()
