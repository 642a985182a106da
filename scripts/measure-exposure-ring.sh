#!/usr/bin/env bash
# The exposure-ring figure (docs/BENCHMARKS.md): snow coverage on open ground 0.2 m from
# the rocks scene's middle boulder against open ground 2-4 m away, in the snow AOV seen
# straight down (scripts/exposure-ring-figure.py explains how distances are found).
# 1.0 means snow reaches the rock's foot; the issue's bound is 0.9 or more.
# Uses an existing build ($WEATHERGEN, default build/weathergen); the images stay in
# $RING_OUT if set. Weather: $RING_WEATHER, by default a snow level that leaves open
# ground partly covered, so that any shelter shows (full cover would hide it).
set -euo pipefail
cd "$(dirname "$0")/.."
wg=${WEATHERGEN:-build/weathergen}
weather=${RING_WEATHER:-temperature=-4,precipitation=0.3,snowLevel=0.3}
out=${RING_OUT:-$(mktemp -d)}
[ -n "${RING_OUT:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
near=25 far=50 size=960x540
render() {  # AOV DISTANCE
  "$wg" render --scene rocks --aov "$1" --weather "$weather" --camera "orbit:0,59,$2" --size "$size" \
    --graphs graphs -o "$out/$1-$2.png" -q
}
render geometricNormal "$near"
render geometricNormal "$far"
render snow "$near"
python3 scripts/exposure-ring-figure.py "$out/geometricNormal-$near.png" "$out/geometricNormal-$far.png" \
  "$out/snow-$near.png" "$near" "$far"
