#!/usr/bin/env bash
# The test suite: install what is missing, build with warnings as errors, run every test
# (Vulkan validation on; a validation message fails the test).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFACET_WERROR=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
