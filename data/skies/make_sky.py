#!/usr/bin/env python3
"""Writes sunny_sky.hdr: a synthetic equirectangular sky for LightLab (256 x 128, Radiance RGBE).

Not a measured sky: a zenith-to-horizon gradient (blue overhead, hazy white at the horizon), a
dark ground below the horizon, and a sun disk of radius 2.5 degrees at 35 degrees elevation whose
radiance makes it about four fifths of the irradiance on a level floor -- a sky whose light is
concentrated in a small bright spot, the case importance sampling by luminance is for.
Layout (scene/environment.h): column u = 0..1 runs once around +y, u = 0.5 looks down -z; row
v = 0..1 from straight up to straight down. Run: python3 data/skies/make_sky.py
"""
import math
import os

W, H = 256, 128
SUN_ELEVATION, SUN_AZIMUTH, SUN_RADIUS = math.radians(35), math.radians(-40), math.radians(2.5)
SUN_RADIANCE = (2600.0, 2400.0, 2100.0)


def direction(u, v):
    phi, theta = (u - 0.5) * 2 * math.pi, v * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def sky(d):
    sun = (math.cos(SUN_ELEVATION) * math.sin(SUN_AZIMUTH), math.sin(SUN_ELEVATION),
           -math.cos(SUN_ELEVATION) * math.cos(SUN_AZIMUTH))
    cos_sun = sum(a * b for a, b in zip(d, sun))
    if cos_sun > math.cos(SUN_RADIUS):
        return SUN_RADIANCE
    if d[1] < 0:  # the ground
        return (0.09, 0.08, 0.07)
    t = d[1] ** 0.5  # 0 at the horizon, 1 overhead
    horizon, zenith = (0.95, 0.95, 1.0), (0.25, 0.42, 0.85)
    glow = 0.6 * max(0.0, cos_sun) ** 8  # brighter around the sun
    return tuple((1 - t) * h + t * z + glow for h, z in zip(horizon, zenith))


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return b"\0\0\0\0"
    e = math.frexp(m)[1]
    scale = 256.0 / 2.0 ** e
    return bytes([min(255, int(x * scale)) for x in c] + [e + 128])


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sunny_sky.hdr")
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
        for y in range(H):
            f.write(b"".join(rgbe(sky(direction((x + 0.5) / W, (y + 0.5) / H))) for x in range(W)))
    print("wrote", out)


if __name__ == "__main__":
    main()
