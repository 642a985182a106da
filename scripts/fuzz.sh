#!/usr/bin/env bash
# Builds the libFuzzer target with clang, ASan and UBSan, and fuzzes the loader and
# compiler for SECONDS (default 600). The seed corpus is graphs/, the bad-input catalog
# and tests/fuzz/regressions. A crash is saved as crash-* in build-fuzz/; copy it into
# tests/fuzz/regressions/ and fix it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
scripts/bootstrap.sh clang libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DWEATHERGEN_SANITIZE="address;undefined" -DWEATHERGEN_FUZZ=ON \
  -DWEATHERGEN_BUILD_TESTS=OFF -DWEATHERGEN_BUILD_BENCH=OFF >/dev/null
ninja -C build-fuzz weathergen_fuzz
[ -x build/weathergen ] || scripts/build.sh  # list-ops feeds the dictionary below
corpus=build-fuzz/corpus
mkdir -p "$corpus"
cp graphs/*.json tests/fuzz/regressions/*.json "$corpus"/
find tests/bad -name '*.json' -type f -exec cp {} "$corpus"/ \;
# A dictionary of the format's words helps the fuzzer build valid graphs.
dict=build-fuzz/graph.dict
{ for w in name nodes output inputs id op param parameters textures weather preset type default \
           switches switch cases values when effects bool on off include \
           file generator wrap filter min mag colorSpace srgb linear alphaMode opaque mask blend alphaCutoff \
           doubleSided; do echo "\"\\\"$w\\\"\""; done
  for op in $(build/weathergen list-ops --json 2>/dev/null | python3 -c 'import json,sys; print(" ".join(o["name"] for o in json.load(sys.stdin)))' 2>/dev/null); do echo "\"\\\"$op\\\"\""; done
} > "$dict"
cd build-fuzz
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
  tests/fuzz/weathergen_fuzz corpus -dict=graph.dict -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=4096
