#!/usr/bin/env bash
# Installs weathergen into a temporary prefix, builds examples/cmake-consumer against it
# with Ninja, and checks the DEPFILE wiring of weathergen_add_materials(): a second build
# does nothing, and touching one image file or one graph re-runs that material alone.
#
# usage: cmake_consumer_test.sh BUILD_DIR SOURCE_DIR [CMAKE] [NINJA]
set -euo pipefail

build_dir=$1
source_dir=$2
cmake=${3:-cmake}
ninja=${4:-ninja}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/wg-cmake-consumer.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Runs a verbose build and prints the materials whose weathergen command ran, sorted.
rebuilt_materials() {
  "$ninja" -C "$tmp/build" -v >"$tmp/ninja.log" 2>&1 || { cat "$tmp/ninja.log" >&2; fail "the build failed"; }
  { grep -o "$tmp/prefix/bin/weathergen compile [^ ]*" "$tmp/ninja.log" || true; } |
    sed 's|.*/||; s|\.json$||' | sort | xargs echo
}

expect_rebuilt() {
  local got
  got=$(rebuilt_materials)
  [[ "$got" == "$1" ]] || { cat "$tmp/ninja.log" >&2; fail "$2: expected '$1' to be compiled, got '$got'"; }
}

expect_no_work() {
  "$ninja" -C "$tmp/build" >"$tmp/ninja.log" 2>&1 || { cat "$tmp/ninja.log" >&2; fail "the build failed"; }
  grep -q "ninja: no work to do." "$tmp/ninja.log" || { cat "$tmp/ninja.log" >&2; fail "$1: the build was not a no-op"; }
}

# touch, made newer than the last build however coarse the file system's clock is.
touch_after_build() {
  touch "$1"
  while [[ ! "$1" -nt "$tmp/build/.ninja_log" ]]; do
    sleep 0.1
    touch "$1"
  done
}

"$cmake" --install "$build_dir" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log" >&2; fail "cmake --install"; }
for f in bin/weathergen lib/cmake/weathergen/weathergenConfig.cmake \
         lib/cmake/weathergen/weathergenConfigVersion.cmake lib/cmake/weathergen/WeathergenMaterials.cmake; do
  [[ -e "$tmp/prefix/$f" ]] || fail "cmake --install did not install $f"
done

# The installed binary knows nothing of the tree it was built in (cache keys stay the
# same across checkouts, docs/scaling.md) and finds the installed bundled graphs.
[[ -e "$tmp/prefix/share/weathergen/graphs/rock.json" ]] || fail "cmake --install did not install the bundled graphs"
if grep -q -F -- "$source_dir" "$tmp/prefix/bin/weathergen"; then
  fail "the installed binary holds the source path $source_dir"
fi
(cd "$tmp" && "$tmp/prefix/bin/weathergen" render --scene rocks --size 32x18 -o "$tmp/rocks.png" -q) ||
  fail "the installed weathergen cannot render with its installed graphs"

# A copy, so touching its files leaves the source tree alone.
cp -R "$source_dir/examples/cmake-consumer" "$tmp/src"
"$cmake" -S "$tmp/src" -B "$tmp/build" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_PREFIX_PATH="$tmp/prefix" >"$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log" >&2; fail "configuring the example"; }

expect_rebuilt "brick_wall muddy_path painted_metal" "first build"
for material in brick_wall muddy_path painted_metal; do
  for suffix in vert.glsl frag.glsl vert.hlsl frag.hlsl reflect.json \
                glsl.vert.spv glsl.frag.spv hlsl.vert.spv hlsl.frag.spv \
                glsl.vert.spvasm glsl.frag.spvasm hlsl.vert.spvasm hlsl.frag.spvasm; do
    [[ -s "$tmp/build/shaders/$material.$suffix" ]] || fail "missing output shaders/$material.$suffix"
  done
done
expect_no_work "second build"

touch_after_build "$tmp/src/materials/textures/mud_albedo.png"
expect_rebuilt "muddy_path" "after touching muddy_path's texture"
expect_no_work "after rebuilding muddy_path"

# The second texture of a material with two: every image is in the depfile.
touch_after_build "$tmp/src/materials/textures/brick_normal.png"
expect_rebuilt "brick_wall" "after touching brick_wall's normal map"
expect_no_work "after rebuilding brick_wall"

# A graph library is in the depfile of the graph that includes it, and of no other.
touch_after_build "$tmp/src/materials/lib/wear.json"
expect_rebuilt "painted_metal" "after touching the library painted_metal includes"
expect_no_work "after rebuilding painted_metal"

# A graph edit also re-runs CMake (the output names come from the graph's "name").
touch_after_build "$tmp/src/materials/painted_metal.json"
expect_rebuilt "painted_metal" "after touching painted_metal.json"
expect_no_work "after rebuilding painted_metal"

echo "cmake_consumer: package installs, example builds, depfiles rebuild one material at a time"
