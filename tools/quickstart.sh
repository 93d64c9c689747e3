#!/usr/bin/env bash
# Quick start: install what is missing, build the facet executable (only what it needs: the test
# command builds the tests and benchmarks), render the showcase scene and its comparison sheet.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
# Unity build: each target's sources compile in batches of 16, parsing the shared headers once per batch.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16
cmake --build build -j"$(nproc)" --target facet
bash tools/showcase.sh build/renderer/cli/facet out
