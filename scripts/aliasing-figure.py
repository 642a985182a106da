#!/usr/bin/env python3
"""The aliasing figure of one view: the mean absolute difference (8-bit sRGB, 0-255,
averaged over R, G and B) between a render SMALL.png and the same view rendered at
k times the width and height (LARGE.png), box-downsampled k x k.

Usage: aliasing-figure.py SMALL.png LARGE.png

Standard library only (zlib): reads 8-bit RGB or RGBA, non-interlaced PNGs, as
`weathergen render` writes them. scripts/measure-aliasing.sh renders the views.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif f == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prev))
        elif f == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif f == 4:
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b, c = prev[i], (prev[i - channels] if i >= channels else 0)
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    w, h, ch, small = read_png(sys.argv[1])
    W, H, CH, large = read_png(sys.argv[2])
    k = W // w
    if k < 1 or W != k * w or H != k * h:
        sys.exit("LARGE must be SMALL's size times a whole number")
    total, n = 0, 0
    for y in range(h):
        block = large[y * k:(y + 1) * k]
        srow = small[y]
        for x in range(w):
            for c in range(3):
                s = 0
                for r in block:
                    base = x * k * CH + c
                    for i in range(k):
                        s += r[base + i * CH]
                total += abs(srow[x * ch + c] - s / (k * k))
                n += 1
    print(f"{total / n:.3f}")


if __name__ == "__main__":
    main()
