#!/usr/bin/env bash
# The main job: set up, build, and compile every bundled graph into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
scripts/build.sh
rm -rf out/materials
build/weathergen compile graphs/*.json -o out/materials --target all
echo "main: wrote $(ls out/materials | wc -l) files for $(ls graphs/*.json | wc -l) materials to out/materials"
