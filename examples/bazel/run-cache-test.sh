#!/usr/bin/env bash
# Proves weathergen outputs are cacheable across machines: builds this example with an
# empty --disk_cache, then again from a fresh output base, then from a copy of the
# workspace at another absolute path. Those two must be full cache hits; a rerun that
# ignores the cache, its actions run as processes of their own instead of by the
# persistent worker, must reproduce the same bytes; after one graph is edited only that
# graph may run. Exits 77 (ctest SKIP) when bazel is not installed.
#
# Usage: examples/bazel/run-cache-test.sh [WEATHERGEN_BINARY]   (default: build/weathergen)
set -euo pipefail

example_dir="$(cd "$(dirname "$0")" && pwd)"
repo_dir="$(cd "$example_dir/../.." && pwd)"
weathergen="$(realpath "${1:-$repo_dir/build/weathergen}")"

if ! command -v bazel >/dev/null; then
  echo "SKIP: bazel is not installed (Debian: apt-get install bazel-bootstrap; scripts/bootstrap.sh does)"
  exit 77
fi
[ -x "$weathergen" ] || { echo "FAIL: no weathergen binary at $weathergen" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/weathergen-bazel.XXXXXX")"
# Bazel leaves its outputs and install files read-only.
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
# Nothing from the caller's home (~/.bazelrc, ~/.cache/bazel) may take part.
export HOME="$work/home"
mkdir -p "$HOME"

# A workspace copy: the example, the binary as tools/weathergen, the bundled graphs.
make_workspace() {
  mkdir -p "$1"
  (cd "$example_dir" && tar cf - --exclude=./tools/weathergen --exclude=./bundled --exclude='./bazel-*' .) |
    tar xf - -C "$1"
  cp "$weathergen" "$1/tools/weathergen"
  mkdir -p "$1/bundled"
  cp "$repo_dir"/graphs/*.json "$1/bundled/"
}

# build NAME WORKSPACE OUTPUT_BASE SPAWNS HITS RUNNER [BAZEL_BUILD_FLAGS...]
build() {
  local name=$1 ws=$2 base=$3 spawns=$4 hits=$5 runner=$6 start=$SECONDS
  shift 6
  echo "== $name: $ws, output base $base $*"
  if ! (cd "$ws" && bazel --batch --nohome_rc --output_base="$base" build --disk_cache="$work/disk-cache" \
        --execution_log_json_file="$work/$name.log.json" "$@" //... >"$work/$name.out" 2>&1); then
    cat "$work/$name.out"
    echo "FAIL: $name: bazel build failed"
    exit 1
  fi
  grep -E "^INFO: [0-9]+ process" "$work/$name.out" || true
  python3 "$example_dir/cache_hits.py" "$work/$name.log.json" "$spawns" "$hits" "$runner" ||
    { echo "FAIL: $name"; exit 1; }
  echo "   $((SECONDS - start)) s"
}

outputs_of() {
  local dirs=("$1"/execroot/weathergen_bazel_example/bazel-out/*/bin)
  [ ${#dirs[@]} -eq 1 ] || { echo "FAIL: expected one bazel-out/*/bin under $1" >&2; exit 1; }
  echo "${dirs[0]}"
}

same_outputs() {
  # The parameter files exist only where an action ran, not where it was a cache hit.
  if ! diff -r --exclude="*.params" "$(outputs_of "$1")" "$(outputs_of "$2")"; then
    echo "FAIL: outputs of $1 and $2 differ"
    exit 1
  fi
}

make_workspace "$work/ws"
graphs=$(( $(ls "$work"/ws/materials/*.json "$work"/ws/bundled/*.json | wc -l) ))

build first "$work/ws" "$work/base-a" "$graphs" 0 worker
build second "$work/ws" "$work/base-b" "$graphs" "$graphs" worker
same_outputs "$work/base-a" "$work/base-b"

# Another absolute path for the workspace and the output base: keys must not change.
make_workspace "$work/elsewhere/deeper/ws"
build moved "$work/elsewhere/deeper/ws" "$work/elsewhere/base-c" "$graphs" "$graphs" worker
same_outputs "$work/base-a" "$work/elsewhere/base-c"

# Cache hits only say the keys matched; running every action again there, ignoring
# the cache, must reproduce the first build's bytes: as processes of their own this
# time (weathergen reads the parameter file with --flagfile), not through the worker.
build rerun "$work/elsewhere/deeper/ws" "$work/elsewhere/base-d" "$graphs" 0 local --noremote_accept_cached \
  --strategy=WeathergenCompile=local
same_outputs "$work/base-a" "$work/elsewhere/base-d"

# One action per graph: editing one graph reruns only that one.
edited="$work/elsewhere/deeper/ws/materials/mossy_stone.json"
sed -i 's/"default": 0.7,/"default": 0.75,/' "$edited"
grep -q '"default": 0.75,' "$edited" || { echo "FAIL: could not edit $edited"; exit 1; }
build edited "$work/elsewhere/deeper/ws" "$work/elsewhere/base-e" "$graphs" $((graphs - 1)) worker
echo "PASS: $graphs materials through the persistent worker: full cache hits from a fresh output base and from another path, reruns as plain processes reproduce the bytes"
