"""Chapter 14's path loop before and after its clean-up, against Embree 3's own path tracer
(`pathtracer` of Debian's embree-tools): one table of samples per second as ratios, and, where
valgrind is installed, the instructions per sample that callgrind counts (the same on any
machine of the same ISA, unlike times on a shared one).

    python3 path_loop.py RTK_BEFORE RTK_AFTER WORK_FOLDER [BUDDHA.obj]

RTK_BEFORE and RTK_AFTER are two builds of `rtk`. The three programs render the same scene
script at 320 x 240, 64 samples per pixel, paths of at most 8 scattering events, on one
thread and on all, one after the other, three times; each figure is the median of the three.
Scenes: Embree's Cornell box script, and, when BUDDHA.obj is given, the 100,000-triangle Happy
Buddha under a point light and a dim sky (the script of equal_time.py). Prints the table
(Markdown)."""
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from equal_time import DEPTH, EMBREE, run, scenes  # noqa: E402

SIZE = (320, 240)
SPP = 64
REPEATS = 3
CALLGRIND = dict(width=80, height=60, spp=8)  # small: callgrind runs 50 times slower


def rtk_render(binary, script, out, threads):
    text = run([binary, "render", "-c", script, "-size", *SIZE, "-spp", SPP, "-depth", DEPTH,
                "-threads", threads, "-seed", 1, "-o", out])
    m = re.search(r"render: .*?: ([0-9.]+) s, .*?(\d+)% of thread time", text)
    return float(m.group(1)), int(m.group(2))


def embree_seconds(script, threads):
    text = run([EMBREE, "-c", script, "--size", *SIZE, "--spp", SPP, "--threads", threads,
                "--max-path-length", DEPTH, "--benchmark", 0, 1])
    return 1.0 / float(re.search(r"BENCHMARK_RENDER_AVG ([0-9.e+-]+)", text).group(1))


def instructions(binary, script, work):
    """Instructions per sample under callgrind, counted inside the tile loop only (not the
    loading and building), with AVX2 kernels (valgrind has no AVX-512), and the share of
    them in the ray kernels."""
    c = CALLGRIND
    out = work / "callgrind.out"
    run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
         "--toggle-collect=*PathTracer::render_tile*", binary, "render", "-c", script, "-size",
         c["width"], c["height"], "-spp", c["spp"], "-depth", DEPTH, "-threads", 1, "-seed", 1,
         "-isa", "avx2", "-o", work / "callgrind.pfm"])
    text = run(["callgrind_annotate", "--inclusive=no", "--threshold=100", out])
    total = kernels = 0
    for line in text.splitlines():
        m = re.match(r"\s*([0-9,]+) \(\s*[0-9.]+%\)\s+(.*)", line)
        if not m:
            continue
        n = int(m.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in m.group(2):
            total = n
        elif re.search(r"traverse_bvhn|intersect_batch|occluded_batch", m.group(2)):
            kernels += n
    samples = c["width"] * c["height"] * c["spp"]
    return total / samples, kernels / max(total, 1)


def main():
    before, after, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    buddha = sys.argv[4] if len(sys.argv) > 4 else None
    work.mkdir(parents=True, exist_ok=True)
    samples = SIZE[0] * SIZE[1] * SPP
    counted = shutil.which("valgrind") and shutil.which("callgrind_annotate")
    print(f"| scene ({SIZE[0]} x {SIZE[1]}, {SPP} spp) | threads | path loop | RTK / Embree "
          "(samples/s) | RTK's time in ray queries |"
          + (" instructions per sample (one thread) | in ray queries |" if counted else ""))
    print("|---|---:|---|---:|---:|" + ("---:|---:|" if counted else ""))
    for label, key, script in scenes(work, buddha):
        for threads in (1, os.cpu_count()):
            times = {"before": [], "after": [], "embree": []}
            shares = {"before": [], "after": []}
            for _ in range(REPEATS):
                for name, binary in (("before", before), ("after", after)):
                    seconds, share = rtk_render(binary, script, work / f"{key}_{name}.pfm", threads)
                    times[name].append(seconds)
                    shares[name].append(share)
                times["embree"].append(embree_seconds(script, threads))
            embree = statistics.median(times["embree"])
            for name, binary in (("before", before), ("after", after)):
                row = (f"| {label} | {threads} | {name} | {embree / statistics.median(times[name]):.2f}x | "
                       f"{statistics.median(shares[name]):.0f} % |")
                if counted and threads == 1:
                    per_sample, in_kernels = instructions(binary, script, work)
                    row += f" {per_sample:,.0f} | {100 * in_kernels:.0f} % |"
                elif counted:
                    row += " | |"
                print(row)
            print(f"<!-- {label}, {threads} threads: Embree {samples / embree / 1e3:.0f} k samples/s, "
                  f"median of {REPEATS} -->", file=sys.stderr)

if __name__ == "__main__":
    main()
