#!/usr/bin/python3
"""Checks the Filament host's frames (tests/package/filament_host_test.sh).

Debian's python3 with python3-numpy and python3-pil (the bootstrap installs them).

usage: filament_compare.py DIR EVAL_JSON
  DIR holds gltfio.png (gltfio's own material), none.png (weathergen's material with
  preset none), and dry.png, snow.png, rain.png (weathergen's weathered material).
  EVAL_JSON: weathergen eval's outputs at each face centre under snow and rain,
  {"snow": {"top": {...}, "front": {...}, "right": {...}}, "rain": {...}, "dry": {...}}.
Prints one line per check and 'N passed, M failed'; exits 1 on any failure.
"""
import json
import math
import sys
from pathlib import Path

import numpy as np
from PIL import Image

# The host's camera (examples/filament-host/filament_host.cpp): the model fitted to
# [-1, 1]^3, seen from EYE with a vertical field of view of 35 degrees.
EYE, WIDTH, HEIGHT, FOV = np.array([2.6, 2.2, 3.4]), 480, 360, 35.0
FACES = {"top": (0.0, 1.0, 0.0), "front": (0.0, 0.0, 1.0), "right": (1.0, 0.0, 0.0)}
RESULTS = {"passed": 0, "failed": 0}


def check(name, ok, detail):
    RESULTS["passed" if ok else "failed"] += 1
    print(("ok     " if ok else "FAILED ") + f"{name}: {detail}")


def pixel(world):
    forward = -EYE / np.linalg.norm(EYE)
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    v = np.asarray(world) - EYE
    depth = v @ forward
    f = 1.0 / math.tan(math.radians(FOV) / 2)
    x = (v @ right) * f / (WIDTH / HEIGHT) / depth
    y = (v @ up) * f / depth
    return int((x * 0.5 + 0.5) * WIDTH), int((0.5 - y * 0.5) * HEIGHT)


def load(folder, name):
    return np.asarray(Image.open(Path(folder) / f"{name}.png").convert("RGB")).astype(float)


def luminance_at(image, face):
    # A window a tenth of the face across, off the logo's edge at the very centre.
    x, y = pixel(np.array(FACES[face]) * 1.0 + np.array([0.3, 0.0, 0.0] if face != "right" else [0.0, 0.0, -0.3]))
    window = image[y - 4:y + 5, x - 4:x + 5]
    return float((window @ [0.2126, 0.7152, 0.0722]).mean())


def main(folder, eval_path):
    coverage = json.loads(Path(eval_path).read_text())
    gltfio, none = load(folder, "gltfio"), load(folder, "none")
    diff = np.abs(gltfio - none)
    check("preset none renders as gltfio's own material", diff.mean() < 2.0 and np.percentile(diff, 99) < 32,
          f"mean |difference| {diff.mean():.2f}/255, 99th percentile {np.percentile(diff, 99):.0f}/255")
    dry, snow, rain = load(folder, "dry"), load(folder, "snow"), load(folder, "rain")
    for face in FACES:
        covered = coverage["snow"][face]["coverage"]["snow"]
        change = luminance_at(snow, face) - luminance_at(dry, face)
        # Where weathergen's evaluator puts snow, Filament's frame turns white, and only there.
        expected = change > 40 if covered > 0.5 else abs(change) < 12
        check(f"snow on the {face} face", expected,
              f"weathergen eval's snow cover {covered:.2f}, Filament's luminance change {change:+.1f}/255")
    for face in FACES:
        wet, dry_out = coverage["rain"][face]["outputs"], coverage["dry"][face]["outputs"]
        darker = luminance_at(rain, face) < luminance_at(dry, face)
        check(f"rain on the {face} face", darker and wet["roughness"] < dry_out["roughness"],
              f"luminance {luminance_at(dry, face):.0f} -> {luminance_at(rain, face):.0f}/255; "
              f"roughness {dry_out['roughness']:.2f} -> {wet['roughness']:.2f} (eval)")
    print(f"{RESULTS['passed']} passed, {RESULTS['failed']} failed")
    return 1 if RESULTS["failed"] else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
