#!/usr/bin/env python3
"""Embree 3's Cornell box script rendered by Embree 3's own pathtracer and by `rtk render
-righthanded`: the two images must agree region by region (a 4 x 4 grid of mean colours), and
RTK's left-handed default must not (it is the mirror image).

usage: embree3_handedness.py RTK SCENES_ROOT WORK_DIR
Exits 77 (skipped) when Embree 3's `pathtracer` (Debian: embree-tools) or the scenes are absent.
"""
import os
import shutil
import subprocess
import sys

GRID = 4


def read_ppm(path):
    data = open(path, "rb").read()
    # P6, width, height, maxval, each on its own token, then the bytes.
    tokens, pos = [], 0
    while len(tokens) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while data[pos:pos + 1] != b"\n":
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        tokens.append(data[start:pos])
    pos += 1
    assert tokens[0] == b"P6", path
    w, h, maxval = int(tokens[1]), int(tokens[2]), int(tokens[3])
    px = data[pos:pos + 3 * w * h]
    return w, h, [c / maxval for c in px]


def regions(image):
    w, h, px = image
    out = []
    for gy in range(GRID):
        for gx in range(GRID):
            s, n = [0.0, 0.0, 0.0], 0
            for y in range(gy * h // GRID, (gy + 1) * h // GRID):
                for x in range(gx * w // GRID, (gx + 1) * w // GRID):
                    i = 3 * (y * w + x)
                    for c in range(3):
                        s[c] += px[i + c]
                    n += 1
            out.append([v / n for v in s])
    return out


def differ(a, b, tolerance):
    """Regions whose mean colours differ by more than `tolerance` of the brighter (plus a floor)."""
    bad = []
    for k, (ra, rb) in enumerate(zip(a, b)):
        for c in range(3):
            if abs(ra[c] - rb[c]) > tolerance * max(ra[c], rb[c]) + 0.02:
                bad.append((k, c, round(ra[c], 3), round(rb[c], 3)))
    return bad


def main():
    rtk, scenes, work = sys.argv[1:4]
    pathtracer = shutil.which("pathtracer")
    e3 = os.path.join(scenes, "embree_models", "v2.17.7_2019", "cornell_box.ecs")
    obj = os.path.join(scenes, "embree_models", "v1.1_release_2012", "cornell_box.obj")
    if not pathtracer or not os.path.exists(e3) or not os.path.exists(obj):
        print("skipped: needs Embree 3's pathtracer (Debian: embree-tools) and the Embree scenes")
        return 77
    os.makedirs(work, exist_ok=True)
    # Embree 3's script names cornell_box.obj beside it; the measured box of Embree 1.1 is it.
    for f in (e3, obj, obj[:-4] + ".mtl"):
        shutil.copy(f, work)
    script = os.path.join(work, "cornell_box.ecs")
    size, spp = "48", "256"
    subprocess.run([pathtracer, "-c", script, "--size", size, size, "--spp", spp,
                    "-o", os.path.join(work, "embree3.ppm")], check=True, stdout=subprocess.DEVNULL)
    for name, handed in (("right", "-righthanded"), ("left", "-lefthanded")):
        subprocess.run([rtk, "render", "-c", script, "-size", size, size, "-spp", spp, handed,
                        "-o", os.path.join(work, name + ".ppm")], check=True, stdout=subprocess.DEVNULL)
    e = regions(read_ppm(os.path.join(work, "embree3.ppm")))
    right = regions(read_ppm(os.path.join(work, "right.ppm")))
    left = regions(read_ppm(os.path.join(work, "left.ppm")))
    bad_right = differ(e, right, 0.25)
    bad_left = differ(e, left, 0.25)
    print("regions differing from Embree 3, right-handed: %d, left-handed: %d" % (len(bad_right), len(bad_left)))
    for b in bad_right:
        print("  right-handed region %d channel %d: Embree 3 %.3f, RTK %.3f" % b)
    if bad_right or not bad_left:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
