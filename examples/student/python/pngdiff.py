#!/usr/bin/env python3
"""Compare two 8-bit PNG images pixel by pixel (standard library only).

    python3 pngdiff.py A.png B.png [--list N]

Reads RGB or RGBA, 8 bits, non-interlaced (what rasterizer.py and most
renderers write), ignores alpha and prints the pixels that differ, the
largest difference per channel, a histogram of the largest channel
difference, and the pixels that only one image covers (non-black).
"""

import argparse
import struct
import sys
import zlib


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def unfilter(raw, width, height, bpp):
    """Undo the five PNG row filters; returns the bytes without filter
    bytes."""
    stride = width * bpp
    out = bytearray(stride * height)
    prev = bytearray(stride)
    pos = 0
    for y in range(height):
        kind = raw[pos]
        row = bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                row[i] = (row[i] + paeth(a, b, c)) & 255
        out[y * stride:(y + 1) * stride] = row
        prev = row
    return out


def read_png(path):
    """(width, height, rgb bytes) of an 8-bit RGB or RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat = 8, bytearray()
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = \
                struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs")
    bpp = 3 if ctype == 2 else 4
    pixels = unfilter(zlib.decompress(bytes(idat)), width, height, bpp)
    if bpp == 4:
        pixels = bytearray(b for i, b in enumerate(pixels) if i % 4 != 3)
    return width, height, pixels


def compare(a, b, width, listed=0):
    """Statistics of the RGB differences between two same-size images."""
    stats = {"differing": 0, "largest": [0, 0, 0], "histogram": {},
             "only_a": 0, "only_b": 0, "examples": []}
    for p in range(len(a) // 3):
        pa, pb = a[3 * p:3 * p + 3], b[3 * p:3 * p + 3]
        if pa == pb:
            continue
        stats["differing"] += 1
        diff = [abs(pa[k] - pb[k]) for k in range(3)]
        for k in range(3):
            stats["largest"][k] = max(stats["largest"][k], diff[k])
        top = max(diff)
        bucket = 1 if top == 1 else 2 if top <= 3 else 4 if top <= 15 \
            else 16 if top <= 63 else 64
        stats["histogram"][bucket] = stats["histogram"].get(bucket, 0) + 1
        a_black, b_black = not any(pa), not any(pb)
        stats["only_a"] += b_black and not a_black
        stats["only_b"] += a_black and not b_black
        if len(stats["examples"]) < listed:
            stats["examples"].append((p % width, p // width, tuple(pa),
                                      tuple(pb)))
    return stats


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--list", type=int, default=0,
                   help="print the first N differing pixels")
    args = p.parse_args()
    wa, ha, a = read_png(args.a)
    wb, hb, b = read_png(args.b)
    if (wa, ha) != (wb, hb):
        sys.exit(f"sizes differ: {wa}x{ha} against {wb}x{hb}")
    s = compare(a, b, wa, args.list)
    print(f"compared {wa * ha} pixels, {s['differing']} differ")
    print(f"largest difference per channel (R, G, B): {s['largest']}")
    names = {1: "1", 2: "2-3", 4: "4-15", 16: "16-63", 64: ">=64"}
    for bucket in sorted(s["histogram"]):
        print(f"  largest channel off by {names[bucket]}: "
              f"{s['histogram'][bucket]}")
    print(f"covered only in {args.a}: {s['only_a']}, "
          f"only in {args.b}: {s['only_b']}")
    for x, y, pa, pb in s["examples"]:
        print(f"  ({x}, {y}): {pa} against {pb}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
