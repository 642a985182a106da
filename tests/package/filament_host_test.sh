#!/usr/bin/env bash
# Filament, a host we did not design for (docs/engine-api.md, "The surface contract"):
#  1. every bundled graph's --target filament material compiles with Debian's matc;
#  2. examples/filament-host builds against the installed package and Debian's
#     libfilament, and renders a real glTF model (assimp-testmodels' BoxTextured.glb)
#     under xvfb-run with Filament's OpenGL backend (llvmpipe);
#  3. the model's imported material with preset none renders as gltfio's own material,
#     snow lies where weathergen's CPU evaluator puts it, rain darkens and smooths.
# The frames stay in $WG_FILAMENT_FRAMES when it is set (scripts/update-readme-images.sh).
#
# usage: filament_host_test.sh BUILD_DIR SOURCE_DIR [CMAKE] [NINJA] [CXX]
set -euo pipefail

build_dir=$1
source_dir=$2
cmake=${3:-cmake}
ninja=${4:-ninja}
cxx=${5:-c++}
cli=$build_dir/weathergen
model=/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb

# shellcheck source=package_steps.sh
source "$(dirname "$0")/package_steps.sh" filament-host "$build_dir" "$cmake"
for tool in matc xvfb-run /usr/bin/python3; do
  command -v "$tool" >/dev/null || fail "$tool is missing: run scripts/bootstrap.sh"
done

# 1. matc accepts every bundled graph's material, for both of Filament's desktop backends.
quiet "compile --target filament" "$cli" compile "$source_dir"/graphs/*.json --target filament -o "$tmp/bundled" -q
pids=()
for mat in "$tmp"/bundled/*.mat; do
  matc -p desktop -a opengl -a vulkan -o "${mat%.mat}.filamat" "$mat" >"${mat%.mat}.matc.log" 2>&1 &
  pids+=($!)
done
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || { cat "$tmp"/bundled/*.matc.log >&2; fail "matc rejected a bundled graph's material"; }
done
echo "matc: $(ls "$tmp"/bundled/*.filamat | wc -l) bundled materials compiled (desktop, OpenGL and Vulkan)"

# 2. The host, built against the installed package.
quiet "configuring examples/filament-host" \
  "$cmake" -S "$source_dir/examples/filament-host" -B "$tmp/host" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix"
quiet "building examples/filament-host" "$ninja" -C "$tmp/host"
host=$tmp/host/filament-host

# 3. The model's material: preset none, and its own weather preset.
quiet "import" "$cli" import "$model" -o "$tmp/model" -q
graph=$tmp/model/BoxTextured_Texture.json
quiet "compile (preset none)" "$cli" compile "$graph" --target filament --weather-preset none -o "$tmp/none" -q
quiet "compile (weathered)" "$cli" compile "$graph" --target filament -o "$tmp/weather" -q
for kind in none weather; do
  quiet "matc ($kind)" matc -p desktop -a opengl -o "$tmp/$kind/material.filamat" "$tmp/$kind/BoxTextured_Texture.mat"
done
frames=${WG_FILAMENT_FRAMES:-$tmp/frames}
mkdir -p "$frames"
render() {
  quiet "rendering $1" xvfb-run -a -s "-screen 0 640x480x24" "$host" "$model" "$frames/$1.png" "${@:2}"
}
render gltfio
render none --material "$tmp/none/material.filamat" --reflection "$tmp/none/BoxTextured_Texture.reflect.json" \
  --textures "$tmp/model"
for weather in dry snow rain; do
  render "$weather" --material "$tmp/weather/material.filamat" --reflection "$tmp/weather/BoxTextured_Texture.reflect.json" \
    --textures "$tmp/model" --weather "${weather/dry/none}"
done

# What weathergen's own evaluator says at the face centres the comparison samples.
eval_at() {  # weather face position normal
  "$cli" eval "$graph" --weather "$("$host" --eval-weather "${1/dry/none}")" --at "worldPosition=$3,normal=$4"
}
{
  echo '{'
  for weather in dry snow rain; do
    echo "\"$weather\": {\"top\": $(eval_at $weather top 0.3:1:0 0:1:0),"
    echo "\"front\": $(eval_at $weather front 0.3:0:1 0:0:1),"
    echo "\"right\": $(eval_at $weather right 1:0:-0.3 1:0:0)}$([[ $weather == rain ]] || echo ,)"
  done
  echo '}'
} >"$tmp/eval.json"
/usr/bin/python3 "$(dirname "$0")/filament_compare.py" "$frames" "$tmp/eval.json"
