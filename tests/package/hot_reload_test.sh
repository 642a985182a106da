#!/usr/bin/env bash
# Installs weathergen into a temporary prefix and checks the engine library in it: the
# header, libweathergen.so exporting only the API, and weathergen::compiler in the CMake
# package. Then builds examples/hot-reload against it with Ninja and runs it (compile
# from memory, Vulkan pipelines from the reflection on lavapipe, validation on, hot
# reload), and checks that add_subdirectory() gives a project weathergen::compiler too.
#
# usage: hot_reload_test.sh BUILD_DIR SOURCE_DIR [CMAKE] [NINJA] [CXX]
set -euo pipefail

build_dir=$1
source_dir=$2
cmake=${3:-cmake}
ninja=${4:-ninja}
cxx=${5:-c++}

# shellcheck source=package_steps.sh
source "$(dirname "$0")/package_steps.sh" hot-reload "$build_dir" "$cmake"
for f in include/weathergen/weathergen.hpp lib/libweathergen.so \
         lib/cmake/weathergen/weathergenConfig.cmake lib/cmake/weathergen/weathergenCompilerTargets.cmake; do
  [[ -e "$prefix/$f" ]] || fail "cmake --install did not install $f"
done

# The header is the only one a user needs: it compiles on its own, warning-free.
echo '#include <weathergen/weathergen.hpp>' >"$tmp/header.cpp"
quiet "the installed header does not compile on its own" \
  "$cxx" -std=c++17 -fsyntax-only -Wall -Wextra -Werror -I"$prefix/include" "$tmp/header.cpp"

# Only the API leaves the library: glslang, SPIRV-Tools, SPIRV-Cross and nlohmann_json
# stay inside, so they cannot clash with an engine's own copies.
leaked=$(nm -D -C --defined-only "$prefix/lib/libweathergen.so" | grep -v ' weathergen::' || true)
[[ -z "$leaked" ]] || fail "libweathergen.so exports more than namespace weathergen:"$'\n'"$leaked"
nm -D -C --defined-only "$prefix/lib/libweathergen.so" | grep -q ' weathergen::compile(' ||
  fail "libweathergen.so does not export weathergen::compile"
# An empty link interface is why the config needs no find_dependency(); a new public
# dependency must come with one.
if grep -q INTERFACE_LINK_LIBRARIES "$prefix/lib/cmake/weathergen/weathergenCompilerTargets.cmake"; then
  fail "weathergen::compiler has link dependencies now: find_dependency() them in weathergenConfig.cmake.in"
fi

quiet "configuring examples/hot-reload against the installed package" \
  "$cmake" -S "$source_dir/examples/hot-reload" -B "$tmp/example" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wno-missing-field-initializers -Werror"
quiet "building examples/hot-reload" "$ninja" -C "$tmp/example"
"$tmp/example/hot_reload" >"$tmp/run.log" 2>&1 || { cat "$tmp/run.log" >&2; fail "hot_reload failed"; }
cat "$tmp/run.log"
[[ $(grep -c ' 2 pipelines;' "$tmp/run.log") == 2 ]] || fail "hot_reload did not build both materials' pipelines"

# add_subdirectory(): the same target name, the public include directory only, no tests.
# Configured and one object compiled; building the library again here would take minutes.
mkdir "$tmp/subdirectory"
cat >"$tmp/subdirectory/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(weathergen_subdirectory_consumer CXX)
add_subdirectory("$source_dir" weathergen)
get_target_property(library weathergen::compiler ALIASED_TARGET)
get_target_property(type "\${library}" TYPE)
if(NOT type STREQUAL "SHARED_LIBRARY")
  message(FATAL_ERROR "weathergen::compiler is '\${library}' (\${type}), not the shared library")
endif()
add_executable(app main.cpp)
target_link_libraries(app PRIVATE weathergen::compiler)
CMAKE
printf '#include <weathergen/weathergen.hpp>\nint main() { return weathergen::version().empty(); }\n' \
  >"$tmp/subdirectory/main.cpp"
quiet "configuring a project that add_subdirectory()s weathergen" \
  "$cmake" -S "$tmp/subdirectory" -B "$tmp/subdirectory/build" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_CXX_COMPILER="$cxx"
quiet "compiling against weathergen::compiler from add_subdirectory()" \
  "$ninja" -C "$tmp/subdirectory/build" CMakeFiles/app.dir/main.cpp.o
commands=$("$ninja" -C "$tmp/subdirectory/build" -t commands app)
grep -q 'libweathergen\.so' <<<"$commands" || fail "app does not link libweathergen.so:"$'\n'"$commands"
compile_line=$(grep -- '-o CMakeFiles/app.dir/main.cpp.o' <<<"$commands")
if grep -q -- "-I$source_dir " <<<"$compile_line"; then
  fail "weathergen::compiler exposes the whole source tree: $compile_line"
fi
if "$ninja" -C "$tmp/subdirectory/build" -t targets all | grep -q weathergen_unit_tests; then
  fail "add_subdirectory(weathergen) builds weathergen's tests by default"
fi

echo "hot_reload: library, header and config installed; pipelines built from the reflection; add_subdirectory works"
