#!/usr/bin/env bash
# Quick start: install what is missing, build the facet executable (only what it needs: the test
# command builds the tests and benchmarks), render the showcase scene and its comparison sheet.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target facet
bash tools/showcase.sh build/renderer/cli/facet out
