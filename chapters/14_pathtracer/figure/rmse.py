"""The root-mean-square error of each render of convergence.sh against the reference, per
sampler and samples per pixel, as a table for convergence.gp.

    python3 rmse.py WORK_FOLDER > TABLE.tsv"""
import math
import pathlib
import struct
import sys


def read_pfm(path):
    data = path.read_bytes()
    parts = data.split(b"\n", 3)  # "PF", "W H", "scale", pixels
    if parts[0].strip() != b"PF":
        raise ValueError(f"{path}: not a colour PFM")
    w, h = map(int, parts[1].split())
    scale = float(parts[2])
    fmt = ("<" if scale < 0 else ">") + "f" * (3 * w * h)
    return struct.unpack(fmt, parts[3][: 12 * w * h])


def main():
    work = pathlib.Path(sys.argv[1])
    ref = read_pfm(work / "reference.pfm")
    print("spp\tindependent\tsobol")
    for spp in (1, 2, 4, 8, 16, 32, 64, 128, 256):
        row = [str(spp)]
        for sampler in ("independent", "sobol"):
            img = read_pfm(work / f"{sampler}-{spp}.pfm")
            row.append(f"{math.sqrt(sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref)):.6f}")
        print("\t".join(row))


if __name__ == "__main__":
    main()
