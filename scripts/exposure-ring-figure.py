#!/usr/bin/env python3
"""The exposure-ring figure of one rock: how much snow lies on open ground near a rock
compared with open ground away from it, from views straight down on the rock.

Usage: exposure-ring-figure.py NEAR_NORMAL.png FAR_NORMAL.png NEAR_SNOW.png NEAR_D FAR_D

NEAR_* are the geometricNormal and snow AOVs of one top-down view (orbit elevation 89)
at orbit distance NEAR_D, FAR_NORMAL the geometricNormal AOV of the same view at FAR_D.
scripts/measure-exposure-ring.sh renders them.

How distances are found, without any scene constant:
- The rock: from straight above, the ground's normals are smooth, so every pixel whose
  normal colour differs from the view's border (ground) colour by more than 48 levels
  is rock; its rim, where the normals turn horizontal, always is, so filling what the
  border cannot reach gives the whole silhouette (the region at the view's centre:
  other rocks may show at the edges). A pixel seen from straight above has
  nothing over it: every other pixel is open ground.
- The scale: a pinhole camera shows the silhouette k = sqrt(area near / area far)
  times larger at NEAR_D than at FAR_D, so the silhouette lies o = (FAR_D - k NEAR_D) /
  (1 - k) beyond the orbit target and NEAR_D - o from the eye; one pixel there is
  2 (NEAR_D - o) tan(20 deg) / height metres (the orbit camera's 40 degree field).
  The rock's foot lies a little below its widest outline: at 25 m, a metre of it
  shifts the scale by 4 %.
- Distances: a chamfer (3-4) distance transform from the silhouette, in pixels, times
  the scale.

Prints, for bands of distance from the silhouette, the mean snow coverage (the AOV's
sRGB decoded to linear) and its ratio to the open-ground reference (2-4 m away), over
the whole outline and in the worst of 12 sectors around it (each against its own
sector's reference), so that a skirt on one side does not average away. The figure is
the worst sector's ratio at 0.15-0.25 m. Standard library only.
"""
import importlib.util
import math
import os
import sys
from collections import deque

_spec = importlib.util.spec_from_file_location(
    "aliasing_figure", os.path.join(os.path.dirname(os.path.abspath(__file__)), "aliasing-figure.py"))
_png = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_png)

ROCK_COLOUR_DISTANCE = 48  # 8-bit levels, summed over R, G and B
FOV_Y_DEGREES = 40.0       # host/scene/orbit_camera.hpp, kOrbitFovYDegrees
REFERENCE_BAND = (2.0, 4.0)
RING_BAND = (0.15, 0.25)
SECTORS = 12
MIN_SECTOR_PIXELS = 50
BANDS = [(0.0, 0.05), (0.05, 0.15), (0.15, 0.25), (0.25, 0.4), (0.4, 0.7), (0.7, 1.0), (1.0, 2.0), REFERENCE_BAND]


def pixels(path):
    w, h, ch, rows = _png.read_png(path)
    return w, h, [[tuple(row[x * ch:x * ch + 3]) for x in range(w)] for row in rows]


def flood(w, h, seeds, passable):
    """The pixels 4-connected to the seeds through passable pixels (a w x h bool grid)."""
    filled = [[False] * w for _ in range(h)]
    for x, y in seeds:
        filled[y][x] = True
    queue = deque(seeds)
    while queue:
        x, y = queue.popleft()
        for nx, ny in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if 0 <= nx < w and 0 <= ny < h and not filled[ny][nx] and passable(nx, ny):
                filled[ny][nx] = True
                queue.append((nx, ny))
    return filled


def rock_mask(path):
    """True where the rock covers the pixel (see the module text)."""
    w, h, px = pixels(path)
    border = [px[y][x] for y in (0, h - 1) for x in range(w)] + [px[y][x] for x in (0, w - 1) for y in range(h)]
    ground = tuple(sorted(c[i] for c in border)[len(border) // 2] for i in range(3))
    edge = [[sum(abs(a - b) for a, b in zip(px[y][x], ground)) > ROCK_COLOUR_DISTANCE for x in range(w)] for y in range(h)]
    # Ground: what the border reaches without crossing an edge pixel.
    reached = flood(w, h, [(x, y) for y in range(h) for x in range(w)
                           if (x in (0, w - 1) or y in (0, h - 1)) and not edge[y][x]], lambda x, y: not edge[y][x])
    # The rock: the unreached region at the view's centre (others may show at the edges).
    cx, cy = w // 2, h // 2
    if reached[cy][cx]:
        sys.exit(f"{path}: no rock at the view's centre")
    mask = flood(w, h, [(cx, cy)], lambda x, y: not reached[y][x])
    return w, h, mask


def distance_pixels(mask, w, h):
    """Chamfer 3-4 distance (in pixels) from the nearest True pixel."""
    inf = 10 ** 9
    d = [[0 if mask[y][x] else inf for x in range(w)] for y in range(h)]
    for y in range(h):
        row, up = d[y], d[y - 1] if y else None
        for x in range(w):
            v = row[x]
            if x:
                v = min(v, row[x - 1] + 3)
            if up:
                v = min(v, up[x] + 3, up[x - 1] + 4 if x else inf, up[x + 1] + 4 if x + 1 < w else inf)
            row[x] = v
    for y in range(h - 1, -1, -1):
        row, down = d[y], d[y + 1] if y + 1 < h else None
        for x in range(w - 1, -1, -1):
            v = row[x]
            if x + 1 < w:
                v = min(v, row[x + 1] + 3)
            if down:
                v = min(v, down[x] + 3, down[x - 1] + 4 if x else inf, down[x + 1] + 4 if x + 1 < w else inf)
            row[x] = v
    return [[v / 3.0 for v in row] for row in d]


def srgb_to_linear(v):
    c = v / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    near_normal, far_normal, near_snow = sys.argv[1:4]
    near_d, far_d = float(sys.argv[4]), float(sys.argv[5])
    w, h, near = rock_mask(near_normal)
    _, _, far = rock_mask(far_normal)
    area_near, area_far = sum(map(sum, near)), sum(map(sum, far))
    if not area_near or not area_far or area_near >= w * h // 2:
        sys.exit("no rock silhouette found in the views")
    k = math.sqrt(area_near / area_far)
    depth = near_d - (far_d - k * near_d) / (1.0 - k)
    metres_per_pixel = 2.0 * depth * math.tan(math.radians(FOV_Y_DEGREES / 2)) / h
    dist = distance_pixels(near, w, h)
    _, _, snow = pixels(near_snow)
    # Sectors around the silhouette's centre: a skirt on one side only (under an
    # overhang, downhill) must not average away against the others.
    cx = sum(x for y in range(h) for x in range(w) if near[y][x]) / area_near
    cy = sum(y for y in range(h) for x in range(w) if near[y][x]) / area_near
    table, sectors = {}, {}
    for y in range(h):
        for x in range(w):
            if near[y][x]:
                continue
            m = dist[y][x] * metres_per_pixel
            coverage = srgb_to_linear(snow[y][x][0])
            sector = int((math.atan2(y - cy, x - cx) + math.pi) / (2 * math.pi) * SECTORS) % SECTORS
            for band in BANDS:
                if band[0] <= m < band[1]:
                    for key, store in ((band, table), ((sector, band), sectors)):
                        s = store.setdefault(key, [0.0, 0])
                        s[0] += coverage
                        s[1] += 1
    if REFERENCE_BAND not in table:
        sys.exit("the view holds no open ground 2-4 m from the rock")

    def mean(store, key):
        return store[key][0] / store[key][1] if key in store and store[key][1] else None

    reference = mean(table, REFERENCE_BAND)
    print(f"silhouette {depth:.1f} m from the eye, {metres_per_pixel * 100:.2f} cm per pixel")
    print("| distance from the silhouette (m) | pixels | snow coverage | / open ground | worst of 12 sectors |")
    print("|---|---|---|---|---|")
    worst = {}
    for band in BANDS:
        ratios = []
        for sector in range(SECTORS):
            near_mean, far_mean = mean(sectors, (sector, band)), mean(sectors, (sector, REFERENCE_BAND))
            if near_mean is not None and far_mean and sectors[(sector, band)][1] >= MIN_SECTOR_PIXELS:
                ratios.append(near_mean / far_mean)
        worst[band] = min(ratios) if ratios else float("nan")
        if band in table:
            print(f"| {band[0]:.2f}-{band[1]:.2f} | {table[band][1]} | {mean(table, band):.3f} | "
                  f"{mean(table, band) / max(reference, 1e-6):.3f} | {worst[band]:.3f} |")
    print(f"figure (0.15-0.25 m / open ground, worst sector): {worst[RING_BAND]:.3f}")

if __name__ == "__main__":
    main()
