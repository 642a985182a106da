#!/usr/bin/env bash
# A deferred host with its own lights and bindings (docs/engine-api.md, "The surface
# contract"): installs weathergen into a temporary prefix, builds examples/engine-plugin
# against it with Ninja and runs it on lavapipe with the validation layers on. The host
# compiles graphs/rock.json's surface, writes its GLSL and HLSL G-buffer glue from the
# reflection alone (every resource moved to its own sets with the WG_ macros), lights
# the G-buffer itself and checks that snow whitened the sphere's top only and that the
# HLSL surface's G-buffer matches the GLSL one's; its weather comes from the installed
# weathergen::weather. Then this script checks its outputs and that library.
# The frames stay in $WG_DEFERRED_FRAMES when it is set.
#
# usage: engine_plugin_test.sh BUILD_DIR SOURCE_DIR [CMAKE] [NINJA] [CXX]
set -euo pipefail

build_dir=$1
source_dir=$2
cmake=${3:-cmake}
ninja=${4:-ninja}
cxx=${5:-c++}

# shellcheck source=package_steps.sh
source "$(dirname "$0")/package_steps.sh" engine-plugin "$build_dir" "$cmake"

# The weather loop's library: its header compiles on its own, and it exports its
# namespace only.
for f in include/weathergen/weather.hpp lib/libweathergen_weather.so lib/cmake/weathergen/weathergenWeatherTargets.cmake; do
  [[ -e "$prefix/$f" ]] || fail "the install lacks $f"
done
echo '#include <weathergen/weather.hpp>' >"$tmp/weather_header.cpp"
quiet "the installed weather header does not compile on its own" \
  "$cxx" -std=c++17 -fsyntax-only -Wall -Wextra -Werror -I"$prefix/include" "$tmp/weather_header.cpp"
leaked=$(nm -D -C --defined-only "$prefix/lib/libweathergen_weather.so" | grep -v ' weathergen::weather::' || true)
[[ -z "$leaked" ]] || fail "libweathergen_weather.so exports more than namespace weathergen::weather:"$'\n'"$leaked"

quiet "configuring examples/engine-plugin against the installed package" \
  "$cmake" -S "$source_dir/examples/engine-plugin" -B "$tmp/example" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wno-missing-field-initializers -Werror"
quiet "building examples/engine-plugin" "$ninja" -C "$tmp/example"

out=${WG_DEFERRED_FRAMES:-$tmp/out}
"$tmp/example/engine_plugin" "$source_dir/graphs/rock.json" "$out" >"$tmp/run.log" 2>&1 ||
  { cat "$tmp/run.log" >&2; fail "engine_plugin failed"; }
cat "$tmp/run.log"
grep -q 'no validation messages$' "$tmp/run.log" || fail "engine_plugin did not finish cleanly"

# Both frames are 256x256 PNGs, and the weather changed the picture.
for state in dry snow; do
  png=$out/deferred-$state.png
  [[ -s "$png" ]] || fail "engine_plugin wrote no $png"
  header=$(head -c 24 "$png" | od -An -tx1 | tr -d ' \n')
  [[ $header == 89504e470d0a1a0a0000000d494844520000010000000100 ]] ||
    fail "$png is not a 256x256 PNG (header $header)"
done
cmp -s "$out/deferred-dry.png" "$out/deferred-snow.png" && fail "the snowy frame is the dry frame"

# The glue moved the surface's resources with its macros, in both languages.
for glue in gbuffer.vert.glsl gbuffer.frag.glsl gbuffer.vert.hlsl gbuffer.frag.hlsl; do
  for define in 'WG_WEATHER_SET 1' 'WG_SET_rock 2' 'WG_BINDING_WeatherBlock 2' 'WG_NO_SKY_EXPOSURE_MAP'; do
    grep -qx "#define $define" "$out/glue/$glue" || fail "$glue does not #define $define"
  done
done

echo "engine_plugin: G-buffer glue from the reflection, resources moved by the WG_ macros, own lights; weather from weathergen::weather; snow on top only; HLSL matches GLSL"
