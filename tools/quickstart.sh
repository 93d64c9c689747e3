#!/usr/bin/env bash
# Quick start: install what is missing, build facet, render the default scene to out/default.exr.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/renderer/cli/facet render scenes/default.json -o out/default.exr
