#!/usr/bin/env bash
# The Bazel example's clean build, its weathergen actions run by one persistent worker
# against one process per action (docs/BENCHMARKS.md, "Bazel: weathergen as a
# persistent worker"). Prints, per round and strategy, the summed wall time of the
# WeathergenCompile actions from Bazel's profile; actions run one at a time (--jobs=1)
# so that they do not share the cores.
#
# Usage: scripts/bench-bazel-worker.sh [ROUNDS] [WEATHERGEN_BINARY]   (default: 3, build/weathergen)
set -euo pipefail

rounds="${1:-3}"
repo_dir="$(cd "$(dirname "$0")/.." && pwd)"
example_dir="$repo_dir/examples/bazel"
weathergen="$(realpath "${2:-$repo_dir/build/weathergen}")"
command -v bazel >/dev/null || { echo "bazel is not installed (apt-get install bazel-bootstrap)" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/weathergen-bazel-bench.XXXXXX")"
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
export HOME="$work/home"
mkdir -p "$HOME" "$work/ws/bundled"
(cd "$example_dir" && tar cf - --exclude=./tools/weathergen --exclude=./bundled --exclude='./bazel-*' .) | tar xf - -C "$work/ws"
cp "$weathergen" "$work/ws/tools/weathergen"
cp "$repo_dir"/graphs/*.json "$work/ws/bundled/"

# The summed duration of the WeathergenCompile actions in a JSON trace profile, in s.
compile_seconds() {
  python3 - "$1" <<'PY'
import gzip, json, sys
with gzip.open(sys.argv[1], "rt") as f:
    events = json.load(f)["traceEvents"]
print("%.2f" % (sum(e.get("dur", 0) for e in events
                    if e.get("cat") == "action processing" and "Compiling material" in e.get("name", "")) / 1e6))
PY
}

for round in $(seq "$rounds"); do
  # Alternate which strategy goes first.
  strategies="local worker"
  [ $((round % 2)) -eq 0 ] && strategies="worker local"
  line="round $round:"
  for strategy in $strategies; do
    base="$work/base-$round-$strategy"
    (cd "$work/ws" && bazel --batch --nohome_rc --output_base="$base" build --jobs=1 \
       --strategy=WeathergenCompile="$strategy" --profile="$work/$round-$strategy.profile.gz" //... \
       >"$work/$round-$strategy.out" 2>&1) || { cat "$work/$round-$strategy.out"; exit 1; }
    line="$line $strategy $(compile_seconds "$work/$round-$strategy.profile.gz") s"
    chmod -R u+w "$base" && rm -rf "$base"
  done
  echo "$line"
done
