#!/usr/bin/env python3
"""Writes the synthetic image pairs of tests/diff/data (8-bit RGB PNGs), Python stdlib only.
(gears_a/b.png are not made here: they are frames rendered by glpt, see flip_reference_test.cpp.)

Each pair NAME_a.png / NAME_b.png exercises one part of FLIP: smooth colour with noise, sharp
edges moved by a pixel, saturated colour changes, a rendered-looking scene with and without
anti-aliasing, and isolated points. Deterministic: rerunning it rewrites identical files.
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(name, width, height, pixel):
    """pixel(x, y) -> (r, g, b) in 0..255."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter type None
        for x in range(width):
            raw.extend(max(0, min(255, int(round(c)))) for c in pixel(x, y))

    def chunk(tag, data):
        body = tag + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9))
    png += chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(png)


def noise(x, y, seed):
    """Deterministic value in [-1, 1] from an integer hash."""
    h = (x * 374761393 + y * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 32767.5 - 1.0


def gradient(x, y):
    return (255 * x / 127, 255 * y / 95, 255 * (1 - x / 127) * 0.8 + 30)


write_png("gradient_a.png", 128, 96, gradient)
write_png("gradient_b.png", 128, 96,
          lambda x, y: tuple(c + 6 * noise(x, y, k) for k, c in enumerate(gradient(x, y))))


def edges(shift):
    def px(x, y):
        x -= shift
        v = 255 if (x // 6) % 2 == 0 else 0          # vertical stripes in the upper half
        if y >= 32:
            v = 230 if x + y < 100 else 20            # a diagonal edge in the lower half
        return (v, v, v)
    return px


write_png("edges_a.png", 96, 64, edges(0))
write_png("edges_b.png", 96, 64, edges(1))

PALETTE = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0), (0, 255, 255), (255, 0, 255),
           (128, 128, 128), (255, 128, 0)]


def colors(permute):
    def px(x, y):
        c = PALETTE[((x // 8) + (y // 8) * 3) % len(PALETTE)]
        if permute and ((x // 8) + (y // 8)) % 3 == 0:
            c = (c[1], c[2], c[0])
        return c
    return px


write_png("colors_a.png", 64, 64, colors(False))
write_png("colors_b.png", 64, 64, colors(True))


def scene(samples):
    """A lit sphere-like disc and a thin line over a dark gradient, `samples`^2 per pixel."""
    def px(x, y):
        acc = [0.0, 0.0, 0.0]
        for sy in range(samples):
            for sx in range(samples):
                fx = x + (sx + 0.5) / samples
                fy = y + (sy + 0.5) / samples
                c = (20 + fy * 0.3, 25 + fy * 0.3, 40 + fy * 0.5)
                dx, dy = fx - 70, fy - 60
                r2 = dx * dx + dy * dy
                if r2 < 40 * 40:
                    nz = math.sqrt(1 - r2 / 1600)
                    light = max(0.0, (-dx * 0.4 - dy * 0.5 + nz * 40 * 0.77) / 40)
                    c = (200 * light + 20, 120 * light + 15, 60 * light + 10)
                if abs(fy - 0.35 * fx - 10) < 0.6:
                    c = (240, 240, 240)
                acc = [a + v for a, v in zip(acc, c)]
        return tuple(a / (samples * samples) for a in acc)
    return px


write_png("scene_a.png", 160, 120, scene(4))
write_png("scene_b.png", 160, 120, scene(1))


def dots(offset):
    def px(x, y):
        if x % 9 == 4 and y % 9 == 4:
            return (250, 250, 250)
        if offset and x % 9 == 0 and y % 9 == 0:
            return (250, 250, 250)
        return (30, 30, 30)
    return px


write_png("dots_a.png", 64, 64, dots(False))
write_png("dots_b.png", 64, 64, dots(True))
