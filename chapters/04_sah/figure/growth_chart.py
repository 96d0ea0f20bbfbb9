"""Chapter 4's growth chart data: build time per triangle and peak memory per triangle of the
tree of the default structure (BVH8, rotations on, leaves priced in blocks of eight) over spheres of
1M, 4M and 16M triangles, from the growth/ benchmarks of `ch04_bench` (JSON; the fastest of
the repetitions when the run repeated: the first build of a size maps its memory afresh, and
what a fresh page costs moves with the machine's other work). One thread: the CPU time of the
building thread, which a shared machine's load does not inflate, and its two parts, the
builder's own (user) time and the kernel's on its behalf (system: mapping fresh memory); two
threads: wall-clock time. The log n column is what one thread's user time per triangle would be
if it grew exactly like log2 n from the smallest scene on.

    python3 growth_chart.py ch04_growth.json OUT.tsv"""
import math
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "scripts"))
import gbench_json  # noqa: E402


def main():
    rows = {}
    for b in gbench_json.repetitions(sys.argv[1]):
        m = re.match(r"growth/[^/]+/[^/]+/tris:(\d+)/threads:(\d+)", b["name"])
        if m:
            rows.setdefault((int(m.group(1)), int(m.group(2))), []).append(b)
    # Per size and thread count, the repetition that built fastest by the time charted.
    rows = {k: min(v, key=lambda b: b["cpu_time" if k[1] == 1 else "real_time"]) for k, v in rows.items()}
    sizes = sorted({n for n, _ in rows})
    first = sizes[0]
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}

    def ns_per_tri(b, n, key):  # the benchmark's time per iteration, per triangle
        return b[key] * scale[b["time_unit"]] / n

    base = rows[(first, 1)]["user_ns/tri"]
    with open(sys.argv[2], "w") as out:
        out.write("triangles\tns/tri 1T\tns/tri 2T\tpeak B/tri 1T\tpeak B/tri 2T\tlog n reference"
                  "\tuser ns/tri 1T\tsystem ns/tri 1T\n")
        for n in sizes:
            one, two = rows[(n, 1)], rows.get((n, 2), rows[(n, 1)])
            ref = base * math.log2(n) / math.log2(first)
            out.write(f"{n}\t{ns_per_tri(one, n, 'cpu_time'):.1f}\t{ns_per_tri(two, n, 'real_time'):.1f}\t"
                      f"{one['peak_B/tri']:.1f}\t{two['peak_B/tri']:.1f}\t{ref:.1f}\t"
                      f"{one['user_ns/tri']:.1f}\t{one['system_ns/tri']:.1f}\n")


if __name__ == "__main__":
    main()
