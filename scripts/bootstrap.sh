#!/usr/bin/env bash
# Installs exactly the Debian 12 packages weathergen needs that are missing, plus any
# extra packages named as arguments (scripts/fuzz.sh asks for clang).
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  python3             # scripts/check-layers.py, the layer check ctest runs
  python3-jsonschema  # tests/surface (Debian's /usr/bin/python3): the surface object against its schema
  glslang-dev glslang-tools spirv-tools libspirv-cross-c-shared-dev
  nlohmann-json3-dev libglm-dev libstb-dev
  rapidjson-dev       # the graph reader's fast JSON front end
  libgtest-dev libbenchmark-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  libtinygltf-dev     # glTF 2.0 import
  libpugixml-dev      # MaterialX import
  assimp-testmodels   # real glTF files the import and model tests read
  bazel-bootstrap  # examples/bazel's cache test (Bazel 4.2 and a JDK)
  libfilament-dev libfilament-tools xvfb xauth  # examples/filament-host: matc, libfilament, xvfb-run
  python3-numpy python3-pil  # tests/package/filament_compare.py (Debian's /usr/bin/python3)
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages present"
  exit 0
fi

echo "bootstrap: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "bootstrap: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
