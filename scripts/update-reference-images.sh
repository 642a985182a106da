#!/usr/bin/env bash
# Regenerates tests/reference/<scene>-<stage>.png: 160x90 frames of every bundled scene
# at every stage of timelines/seasons.json, rendered on lavapipe.
# Review the images (and git diff --stat) before committing: references change only here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for scene in $(build/weathergen list-scenes | cut -f1); do
  build/weathergen render --scene "$scene" --timeline timelines/seasons.json --step 300 --no-precipitation \
    --size 160x90 --device cpu --frames tests/reference -o "$tmp/$scene.png" -q
done
git --no-pager diff --stat -- tests/reference || true
echo "update-reference-images: $(ls tests/reference/*.png | wc -l) images in tests/reference"
