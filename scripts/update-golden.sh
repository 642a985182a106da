#!/usr/bin/env bash
# Regenerates tests/golden/*.spvasm (SPIR-V at -O0) and the surfaces (*.surface.*) from
# the bundled graphs.
# Review the diff (git diff tests/golden) before committing: goldens change only here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
build/weathergen compile graphs/*.json --target spirv,surface -O0 -o "$tmp"
rm -f tests/golden/*.spvasm tests/golden/*.surface.*
cp "$tmp"/*.spvasm "$tmp"/*.surface.* tests/golden/
git --no-pager diff --stat -- tests/golden || true
echo "update-golden: $(ls tests/golden | wc -l) files in tests/golden; review with: git diff tests/golden"
