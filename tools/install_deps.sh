#!/usr/bin/env bash
# Installs the Debian 12 packages facet builds and tests with, if any is missing, plus any
# packages named as arguments.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libglm-dev libopenexr-dev libpng-dev libtinygltf-dev libstb-dev nlohmann-json3-dev
  libtbb-dev libcli11-dev libboost-dev libembree-dev libfftw3-dev libxxhash-dev
  libgtest-dev libbenchmark-dev
  openimageio-tools hyperfine
)
packages+=("$@")  # extra packages a caller needs (tools/test.sh: clang-16)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "facet: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
