#!/usr/bin/env bash
# The aliasing figure (docs/BENCHMARKS.md): per scene, each lit view at 320x180 against
# the same view at 1280x720 box-downsampled 4x4, as the mean absolute difference in
# 8-bit sRGB (scripts/aliasing-figure.py), in the default weather (dry: nothing falls).
# Lower is better; 0 would be a perfect filter.
# Uses an existing build (build/weathergen); the images stay in $ALIASING_OUT if set.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${ALIASING_OUT:-$(mktemp -d)}
[ -n "${ALIASING_OUT:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
echo "| scene | aliasing figure (MAD, 0-255) |"
echo "|---|---|"
for scene in $(build/weathergen list-scenes | cut -f1); do
  for size in 320x180 1280x720; do
    build/weathergen render --scene "$scene" --size "$size" -o "$out/$scene-$size.png" -q
  done
  echo "| $scene | $(python3 scripts/aliasing-figure.py "$out/$scene-320x180.png" "$out/$scene-1280x720.png") |"
done
