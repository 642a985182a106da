#!/usr/bin/env bash
# Installs weathergen into a temporary prefix and checks the deformable snow library in
# it: the header (compiles on its own), libweathergen_snow.so exporting only
# weathergen::snow, and weathergen::snow in the CMake package. Then builds
# examples/snow-plugin against it with Ninja and runs it on lavapipe with the validation
# layers on: any validation message, Vulkan error or a walk without prints fails.
#
# usage: snow_plugin_test.sh BUILD_DIR SOURCE_DIR [CMAKE] [NINJA] [CXX]
set -euo pipefail

build_dir=$1
source_dir=$2
cmake=${3:-cmake}
ninja=${4:-ninja}
cxx=${5:-c++}

# shellcheck source=package_steps.sh
source "$(dirname "$0")/package_steps.sh" snow-plugin "$build_dir" "$cmake"
for f in include/weathergen/snow.hpp lib/libweathergen_snow.so lib/cmake/weathergen/weathergenSnowTargets.cmake; do
  [[ -e "$prefix/$f" ]] || fail "cmake --install did not install $f"
done

echo '#include <weathergen/snow.hpp>' >"$tmp/header.cpp"
quiet "the installed snow header does not compile on its own" \
  "$cxx" -std=c++17 -fsyntax-only -Wall -Wextra -Werror -I"$prefix/include" "$tmp/header.cpp"

# Only the API leaves the library: the runtime, glslang and SPIRV-Cross stay inside.
leaked=$(nm -D -C --defined-only "$prefix/lib/libweathergen_snow.so" | grep -v ' weathergen::snow::' || true)
[[ -z "$leaked" ]] || fail "libweathergen_snow.so exports more than namespace weathergen::snow:"$'\n'"$leaked"
nm -D -C --defined-only "$prefix/lib/libweathergen_snow.so" | grep -q 'weathergen::snow::DeformableSnow::record' ||
  fail "libweathergen_snow.so does not export DeformableSnow::record"

quiet "configuring examples/snow-plugin against the installed package" \
  "$cmake" -S "$source_dir/examples/snow-plugin" -B "$tmp/example" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wno-missing-field-initializers -Werror"
quiet "building examples/snow-plugin" "$ninja" -C "$tmp/example"
(cd "$tmp/example" && ./snow_plugin) >"$tmp/run.log" 2>&1 || { cat "$tmp/run.log" >&2; fail "snow_plugin failed"; }
cat "$tmp/run.log"
grep -q ' 0 validation messages$' "$tmp/run.log" || fail "snow_plugin saw validation messages"
[[ -s "$tmp/example/snow_surface.pgm" ]] || fail "snow_plugin wrote no snow_surface.pgm"
[[ $(head -c 8 "$tmp/example/snow_prints.wgprints") == WGPRINTS ]] || fail "snow_plugin saved no prints file"

echo "snow_plugin: library, header and config installed; a scripted walk recorded into the engine's frames"
