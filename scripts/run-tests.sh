#!/usr/bin/env bash
# Sets up, builds and runs every test (ctest), then the whole suite once more built
# with AddressSanitizer and UndefinedBehaviorSanitizer. Exit status is non-zero if
# either run fails.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)

# The sanitizer pass: a separate build tree, tests only.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWEATHERGEN_SANITIZE="address;undefined" \
  -DWEATHERGEN_BUILD_BENCH=OFF >/dev/null
ninja -C build-asan -j"$(nproc)"
# Leaks inside the Vulkan driver (lavapipe, LLVM) are not ours: tests/sanitizers/lsan.supp.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
(cd build-asan && ctest --output-on-failure -j"$(nproc)" --timeout 1200)
