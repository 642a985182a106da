#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, ASan and UBSan, and runs one for SECONDS
# (default 600):
#   scripts/fuzz.sh [SECONDS] [graph|timeline|cli-options]
# graph (the default): graph files and the graph libraries they include, through the
#   loader and the compiler; seeds: graphs/, the bad-input catalog, the examples with
#   their libraries and tests/fuzz/regressions.
# timeline: `render --timeline` files; seeds: timelines and the regressions' timeline/.
# cli-options: NUL-separated arguments for the CLI's option parsers; seeds: the regressions' cli_options/.
# A crash is saved as crash-* in build-fuzz/; copy it into tests/fuzz/regressions/ (or
# its timeline/ or cli_options/) and fix it. Rerun the target on the file to see which
# property broke.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
target="${2:-graph}"
case "$target" in
  graph) binary=weathergen_fuzz ;;
  timeline) binary=weathergen_timeline_fuzz ;;
  cli-options) binary=weathergen_cli_options_fuzz ;;
  *) echo "usage: scripts/fuzz.sh [SECONDS] [graph|timeline|cli-options]" >&2; exit 2 ;;
esac
command -v clang++ >/dev/null && [ -n "$(find /usr/lib/llvm-14 -name 'libclang_rt.fuzzer-x86_64.a' 2>/dev/null)" ] ||
  scripts/bootstrap.sh clang libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes
[ -f build-fuzz/build.ninja ] ||
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DWEATHERGEN_SANITIZE="address;undefined" -DWEATHERGEN_FUZZ=ON \
    -DWEATHERGEN_BUILD_TESTS=OFF -DWEATHERGEN_BUILD_BENCH=OFF >/dev/null
ninja -C build-fuzz "$binary"

corpus=build-fuzz/corpus-$target
mkdir -p "$corpus"
dict=build-fuzz/$target.dict
options=()
case "$target" in
  graph)
    [ -x build/weathergen ] || scripts/build.sh  # list-ops feeds the dictionary below
    cp graphs/*.json tests/fuzz/regressions/*.json "$corpus"/
    find tests/bad -name '*.json' -type f -exec cp {} "$corpus"/ \;
    # Each example graph with its libraries, as one input (tests/fuzz/graph_with_libraries.hpp).
    python3 - "$corpus" examples <<'PY'
import json, pathlib, sys
corpus, root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
for graph in root.rglob("*.json"):
    try:
        doc = json.loads(graph.read_text())
    except ValueError:
        continue
    if not isinstance(doc, dict) or not isinstance(doc.get("include"), dict):
        continue
    libraries = []
    for alias, path in list(doc["include"].items())[:4]:
        libraries.append((graph.parent / path).read_text())
        doc["include"][alias] = f"lib{len(libraries)}.json"
    (corpus / f"example-{graph.stem}.json").write_text("\n---\n".join([json.dumps(doc, indent=1)] + libraries))
PY
    # A dictionary of the format's words helps the fuzzer build valid graphs.
    { for w in name nodes output inputs id op param parameters textures weather preset type default \
               switches switch cases values when effects bool on off include lib1.json lib2.json \
               file generator wrap filter min mag colorSpace srgb linear alphaMode opaque mask blend alphaCutoff \
               doubleSided; do echo "\"\\\"$w\\\"\""; done
      echo '"\x0a---\x0a"'
      for op in $(build/weathergen list-ops --json 2>/dev/null | python3 -c 'import json,sys; print(" ".join(o["name"] for o in json.load(sys.stdin)))' 2>/dev/null); do echo "\"\\\"$op\\\"\""; done
    } > "$dict"
    options=(-max_len=65536) ;;
  timeline)
    cp timelines/*.json tests/fuzz/regressions/timeline/* "$corpus"/
    for w in keyframes time temperature precipitation wind windIntensity label; do echo "\"\\\"$w\\\"\""; done > "$dict"
    options=(-max_len=16384) ;;
  cli-options)
    cp tests/fuzz/regressions/cli_options/* "$corpus"/
    # Every option and eval input name; usage errors print to stderr, so the target's
    # output is closed (rerun a crash without -close_fd_mask to read it).
    { for w in --scene --material --model --preset-map --model-scale --camera -o --output --timeline --aov \
               --device --graphs --frames --weather --weather-preset --backend --size --step --watch-renders \
               --validation --no-shadows --no-precipitation --quiet --watch --snow-displacement --help -- orbit: glsl hlsl \
               temperature precipitation windDirection windIntensity sunDirection sunIntensity snowLevel \
               wetnessLevel mossLevel frostLevel puddleLevel time terrainHeightScale worldPosition normal tangent texcoord vertexColor skyExposure \
               scale offset tint colour wet true false; do echo "\"$w\""; done
      printf '"\\x00"\n"="\n":"\n","\n"e-"\n'
    } > "$dict"
    options=(-max_len=4096 -close_fd_mask=3) ;;
esac
cd build-fuzz
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
  "tests/fuzz/$binary" "corpus-$target" -dict="$target.dict" -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=4096 "${options[@]}"
