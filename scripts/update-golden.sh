#!/usr/bin/env bash
# Regenerates tests/golden/*.spvasm from the bundled graphs (SPIR-V at -O0).
# Review the diff (git diff tests/golden) before committing: goldens change only here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
build/weathergen compile graphs/*.json --target spirv -O0 -o "$tmp"
rm -f tests/golden/*.spvasm
cp "$tmp"/*.spvasm tests/golden/
git --no-pager diff --stat -- tests/golden || true
echo "update-golden: $(ls tests/golden/*.spvasm | wc -l) files in tests/golden; review with: git diff tests/golden"
