#!/usr/bin/env bash
# The test suite (README, .ci/run). One build serves everything: clang-16 with AddressSanitizer +
# UndefinedBehaviorSanitizer and libFuzzer coverage on every target, warnings as errors. Then:
#   1. every test (Vulkan validation on: a validation message or a sanitizer report fails the test),
#      including the replay of every fuzz corpus and regression input;
#   2. every fuzz target for FUZZ_SECONDS (default 15), two at a time (docs/hardening.md).
# (clang-14, Debian's default, cannot compile the shared kernels' C++20 parenthesized aggregate
# initialisation; tools/quickstart.sh builds with gcc.)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
bash tools/install_deps.sh clang-16 libclang-rt-16-dev ninja-build
# Ninja compiles a target's sources while the libraries it links are still being built (make waits
# for each library), which keeps both cores busy along the library chain.
if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
# A unity build (16 sources of a target per compiler run) parses the heavy headers once per batch:
# renderer/scene's objects took 88 s of CPU one by one, 35 s together (clang-16, ASan, 2026-11-25).
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-16 -DCMAKE_BUILD_TYPE=Release -DFACET_WERROR=ON \
  -DFACET_SANITIZE=address,undefined -DFACET_FUZZ=ON -DFACET_BUILD_BENCHMARKS=OFF \
  -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16
cmake --build "$build" -j"$(nproc)"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" --timeout 900
bash tools/fuzz_all.sh "${FUZZ_SECONDS:-15}" "$build"
