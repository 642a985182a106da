#!/bin/sh
# Registers, instructions and waves per SIMD of each bundled graph's lit pipeline, as
# AMD's shader compiler (Mesa RADV's ACO) builds them, weathered and with preset none,
# at each quality tier. No GPU is needed: RADV_FORCE_FAMILY makes RADV offer a null
# device of that GPU family (Mesa 22.3, Debian 12's mesa-vulkan-drivers), which compiles
# pipelines but runs nothing.
#
#   scripts/gpu-shader-stats.sh [FAMILY] [tool options...] [GRAPH...]
#   FAMILY: navi21 (RDNA2, the default), navi10, vega10, gfx1100 ...
set -eu
cd "$(dirname "$0")/.."
family=${1:-navi21}
[ $# -gt 0 ] && shift
tool=build/bench/weathergen_gpu_shader_stats
[ -x "$tool" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
if [ $# -eq 0 ]; then set -- graphs/*.json; fi
device=$(echo "$family" | tr '[:lower:]' '[:upper:]')
RADV_FORCE_FAMILY=$family exec "$tool" --device "$device" "$@"
