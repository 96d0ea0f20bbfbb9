"""Chapter 14 against Embree 3's own path tracer (`pathtracer` of Debian's embree-tools), on the
same scene scripts: samples per second at equal size, samples and threads, and error against
time for each of RTK's samplers and for Embree, each against its own converged image.

    python3 equal_time.py RTK WORK_FOLDER CHAPTER_FOLDER [BUDDHA.obj]

Scenes: Embree's Cornell box script (/usr/share/doc/embree3/models/cornell_box.ecs), and, when
BUDDHA.obj is given, the 100,000-triangle Happy Buddha under a point light and a uniform sky
(a script both programs read, written into WORK_FOLDER). Both renderers trace paths of at most
8 scattering events (RTK's -depth 8, Embree's --max-path-length 8).

Writes into CHAPTER_FOLDER: ch14_vs_embree.md (the throughput table), ch14_equal_time.tsv and
.png (the chart) and ch14_equal_time.md (the error ratio at equal time). Raw output stays in
WORK_FOLDER.

Embree's program writes 8-bit images (its linear colour clamped to [0, 1] and truncated), so
for this comparison RTK's images are put through the same clamp and truncation, and every
error is the relative RMS error of such images against the same program's converged image
treated the same way. `rtk render -reference` prints the linear figure besides; the two
differ little except where pixels are brighter than 1 (the light itself)."""
import math
import os
import pathlib
import re
import statistics
import struct
import subprocess
import sys

EMBREE = "pathtracer"
CORNELL = pathlib.Path("/usr/share/doc/embree3/models/cornell_box.ecs")
DEPTH = 8
THROUGHPUT = dict(width=320, height=240, spp=64, repeats=2)
CHART = dict(width=160, height=120, reference_spp=1024)
RTK_TIMES = (0.5, 1, 2)
SPP = (1, 2, 4, 8, 16, 32, 64)


def run(cmd):
    out = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"equal_time.py: {' '.join(map(str, cmd))} failed:\n{out.stdout}{out.stderr}")
    return out.stdout + out.stderr


def read_pfm(path):
    data = pathlib.Path(path).read_bytes()
    parts = data.split(b"\n", 3)  # "PF", "W H", "scale", pixels
    if parts[0].strip() != b"PF":
        raise ValueError(f"{path}: not a colour PFM")
    w, h = map(int, parts[1].split())
    fmt = ("<" if float(parts[2]) < 0 else ">") + "f" * (3 * w * h)
    return struct.unpack(fmt, parts[3][: 12 * w * h])


def display(values):
    """What Embree's program writes: each channel clamped to [0, 1] and truncated to 8 bits."""
    return [math.floor(255.01 * min(max(v, 0.0), 1.0)) / 255.0 for v in values]


def relative_rms(image, reference):
    err = sum((a - b) ** 2 for a, b in zip(image, reference))
    return math.sqrt(err / sum(b * b for b in reference))


class Rtk:
    name = "RTK"

    def __init__(self, binary):
        self.binary = binary

    def render(self, script, w, h, threads, out, spp=None, seconds=None, sampler="sobol", seed=1,
               reference=None):
        cmd = [self.binary, "render", "-c", script, "-size", w, h, "-depth", DEPTH, "-threads", threads,
               "-sampler", sampler, "-seed", seed]
        cmd += ["-spp", spp] if seconds is None else ["-time", seconds]
        if reference:
            cmd += ["-reference", reference]
        cmd += ["-o", out]  # last: an -o renders the state set up before it
        text = run(cmd)
        m = re.search(r"render: \d+x\d+, (\d+) spp.*?: ([0-9.]+) s, ([0-9.e+]+) samples/s.*?(\d+)% of thread time", text)
        if not m:
            sys.exit(f"equal_time.py: no render line in:\n{text}")
        e = re.search(r"error: ([0-9.e+-]+)", text)
        return dict(spp=int(m.group(1)), seconds=float(m.group(2)), samples_per_s=float(m.group(3)),
                    ray_share=int(m.group(4)), linear_error=float(e.group(1)) if e else None)


class Embree:
    name = "Embree 3 pathtracer"

    def common(self, script, w, h, spp, threads):
        return [EMBREE, "-c", script, "--size", w, h, "--spp", spp, "--threads", threads,
                "--max-path-length", DEPTH]

    def seconds(self, script, w, h, spp, threads):
        """Rendering time of one frame (no loading or building), from its benchmark mode."""
        text = run(self.common(script, w, h, spp, threads) + ["--benchmark", 0, 1])
        fps = float(re.search(r"BENCHMARK_RENDER_AVG ([0-9.e+-]+)", text).group(1))
        return 1.0 / fps

    def image(self, script, w, h, spp, threads, out):
        run(self.common(script, w, h, spp, threads) + ["-o", out])


def scenes(work, buddha):
    found = [("Cornell box (Embree's script, 34 triangles)", "cornell", CORNELL)]
    if buddha:
        script = work / "buddha.ecs"
        # Seen from the front and a little above, lit by a point light and a dim sky.
        # Embree's program names files relative to the script's folder, even absolute ones.
        mesh = os.path.relpath(pathlib.Path(buddha).resolve(), work.resolve())
        script.write_text(f"-i {mesh}\n"
                          "-pointlight 2 3 3 20 20 20\n-ambientlight 0.4 0.4 0.4\n"
                          "-vp 0 0 2.6 -vi 0 0 0 -vu 0 1 0 -fov 45\n")
        found.append(("Happy Buddha (100,000 triangles)", "buddha", script))
    return found


def throughput(rtk, embree, work, scene_list, threads_all):
    """Samples per second of both programs, alternating runs so that they share the machine's
    moods; the median of the repeats."""
    t = THROUGHPUT
    samples = t["width"] * t["height"] * t["spp"]
    rows = []
    for label, key, script in scene_list:
        for threads in (1, threads_all):
            r_rates, r_share, e_rates = [], [], []
            for _ in range(t["repeats"]):
                r = rtk.render(script, t["width"], t["height"], threads, work / f"{key}_tp.pfm", spp=t["spp"])
                r_rates.append(r["samples_per_s"])
                r_share.append(r["ray_share"])
                e_rates.append(samples / embree.seconds(script, t["width"], t["height"], t["spp"], threads))
            rows.append((label, threads, statistics.median(r_rates), statistics.median(e_rates),
                         statistics.median(r_share)))
    return rows


def chart(rtk, embree, work, scene_list):
    """(scene key, program, seconds, display-space error, linear error or None, spp) per run.

    Each program renders 1 to 64 samples per pixel, and its time for N samples is N times its
    median time per sample over those runs: on a shared machine a single run's time can be
    doubled by a neighbour, while the error of N samples does not depend on the machine. RTK's
    -time runs are kept as they were measured (program "RTK sobol -time")."""
    c = CHART
    w, h = c["width"], c["height"]
    points = []
    for label, key, script in scene_list:
        ref_rtk, ref_emb = work / f"{key}_rtk_ref.pfm", work / f"{key}_embree_ref.pfm"
        rtk.render(script, w, h, 0, ref_rtk, spp=c["reference_spp"], seed=99)
        embree.image(script, w, h, c["reference_spp"], os.cpu_count(), ref_emb)
        ref_rtk_display = display(read_pfm(ref_rtk))
        ref_emb_display = read_pfm(ref_emb)
        runs = {}
        for sampler in ("independent", "sobol"):
            for spp in SPP:
                out = work / f"{key}_rtk_{sampler}_{spp}.pfm"
                r = rtk.render(script, w, h, 1, out, spp=spp, sampler=sampler, reference=ref_rtk)
                err = relative_rms(display(read_pfm(out)), ref_rtk_display)
                runs.setdefault(f"RTK {sampler}", []).append((r["seconds"], err, r["linear_error"], spp))
        for spp in SPP:
            out = work / f"{key}_embree_{spp}.pfm"
            embree.image(script, w, h, spp, 1, out)
            seconds = embree.seconds(script, w, h, spp, 1)
            runs.setdefault("Embree", []).append((seconds, relative_rms(read_pfm(out), ref_emb_display), None, spp))
        for program, rs in runs.items():
            per_sample = statistics.median(t / spp for t, _, _, spp in rs)
            points += [(key, program, spp * per_sample, err, lin, spp) for _, err, lin, spp in rs]
        for seconds in RTK_TIMES:
            out = work / f"{key}_rtk_time_{seconds}.pfm"
            r = rtk.render(script, w, h, 1, out, seconds=seconds, reference=ref_rtk)
            err = relative_rms(display(read_pfm(out)), ref_rtk_display)
            points.append((key, "RTK sobol -time", r["seconds"], err, r["linear_error"], r["spp"]))
    return points


def error_at(points, seconds):
    """The error of a program at `seconds`, interpolated on log-log axes between its runs
    (whose times, being spp times a cost per sample, grow with spp)."""
    pts = sorted((p[2], p[3]) for p in points)
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if t0 <= seconds <= t1:
            f = (math.log(seconds) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return None


def main():
    rtk_binary, work, chapter = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    buddha = sys.argv[4] if len(sys.argv) > 4 else None
    work.mkdir(parents=True, exist_ok=True)
    rtk, embree = Rtk(rtk_binary), Embree()
    scene_list = scenes(work, buddha)
    threads_all = os.cpu_count()
    made_by = "<!-- Generated by scripts/measure.sh ch14_equal_time; do not edit. -->\n"

    rows = throughput(rtk, embree, work, scene_list, threads_all)
    t = THROUGHPUT
    with open(chapter / "ch14_vs_embree.md", "w") as f:
        f.write(made_by)
        f.write(f"| scene ({t['width']} x {t['height']}, {t['spp']} spp) | threads | RTK samples/s | "
                "Embree samples/s | RTK / Embree | RTK's time in ray queries |\n")
        f.write("|---|---:|---:|---:|---:|---:|\n")
        for label, threads, r, e, share in rows:
            f.write(f"| {label} | {threads} | {r / 1e3:.0f} k | {e / 1e3:.0f} k | {r / e:.2f}x | {share:.0f} % |\n")

    points = chart(rtk, embree, work, scene_list)
    with open(chapter / "ch14_equal_time.tsv", "w") as f:
        f.write("scene\tprogram\tseconds\terror\tlinear_error\tspp\n")
        for key, program, seconds, err, lin, spp in points:
            f.write(f"{key}\t{program}\t{seconds:.4f}\t{err:.6f}\t{'' if lin is None else f'{lin:.6f}'}\t{spp}\n")
    with open(chapter / "ch14_equal_time.md", "w") as f:
        f.write(made_by)
        f.write(f"| scene ({CHART['width']} x {CHART['height']}, one thread) | RTK's spp (Sobol) | its time | "
                "RTK's error | Embree's error at that time | RTK / Embree |\n")
        f.write("|---|---:|---:|---:|---:|---:|\n")
        labels = {key: label for label, key, _ in scene_list}
        for key in labels:
            emb = [p for p in points if p[0] == key and p[1] == "Embree"]
            for p in points:
                if p[0] != key or p[1] != "RTK sobol":
                    continue
                e = error_at(emb, p[2])
                ratio = f"{p[3] / e:.2f}" if e else "(outside Embree's runs)"
                shown = f"{e:.4f}" if e else "-"
                f.write(f"| {labels[key]} | {p[5]} | {p[2]:.2f} s | {p[3]:.4f} | {shown} | {ratio} |\n")
    print(open(chapter / "ch14_vs_embree.md").read())
    print(open(chapter / "ch14_equal_time.md").read())


if __name__ == "__main__":
    main()
