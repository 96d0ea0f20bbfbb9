#!/usr/bin/env python3
"""Writes sky.hdr, the environment map of environment.ecs: a latitude-longitude image (row 0
the zenith, +y up, as chapter 13's EnvironmentLight reads it) of a blue sky that brightens
toward the horizon, a darker ground, and a small sun 35 degrees above the horizon that is
some thousand times brighter than the sky, the case importance sampling of the map is for.
Radiance RGBE, flat (unencoded) scanlines, which every reader accepts. Run: python3 make_sky.py"""
import math
import struct

W, H = 128, 64
SUN_THETA, SUN_PHI, SUN_SIZE = math.radians(55.0), math.radians(200.0), math.radians(3.0)


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    mant, exp = math.frexp(m)
    scale = mant * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), exp + 128))


def radiance(theta, phi):
    d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
    s = (math.sin(SUN_THETA) * math.cos(SUN_PHI), math.cos(SUN_THETA), math.sin(SUN_THETA) * math.sin(SUN_PHI))
    if math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(d, s))))) < SUN_SIZE:
        return (2000.0, 1800.0, 1500.0)
    if d[1] < 0.0:
        return (0.25, 0.22, 0.18)
    t = d[1]
    return (0.9 - 0.6 * t, 1.0 - 0.45 * t, 1.2 - 0.1 * t)


with open("sky.hdr", "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
    f.write(b"-Y %d +X %d\n" % (H, W))
    for y in range(H):
        theta = (y + 0.5) / H * math.pi
        for x in range(W):
            f.write(rgbe(*radiance(theta, (x + 0.5) / W * 2.0 * math.pi)))
