#!/usr/bin/env bash
# The hardening stage of the test suite, run after tools/test.sh's main (gcc, -Werror) suite
# (docs/hardening.md). ONE extra build serves both sanitizers and fuzzing: clang-16 with
# -fsanitize=address,undefined on every target and -fsanitize=fuzzer-no-link, so the libFuzzer
# programs link against the same instrumented libraries.
#   1. the whole ctest suite (incl. the fuzz regression replays) under ASan + UBSan, on lavapipe;
#   2. every fuzz target for FUZZ_SECONDS (default 30), two at a time on the 2 cores.
# (clang-14, Debian's default, cannot compile the shared kernels: C++20 parenthesized aggregate
# initialisation needs clang 16.)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
seconds=${FUZZ_SECONDS:-30}
jobs=$(nproc)
bash tools/install_deps.sh clang-16 libclang-rt-16-dev
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++-16 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DFACET_SANITIZE=address,undefined -DFACET_FUZZ=ON -DFACET_BUILD_BENCHMARKS=OFF
cmake --build "$build" -j"$jobs"
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 900

targets=$(sed -n 's/^facet_add_fuzz_target(NAME \([a-z_]*\) .*/\1/p' fuzz/CMakeLists.txt)
failed=0
run_one() {
  if bash tools/fuzz_long.sh "$1" "$seconds" "$build" > "$build/fuzz-$1.log" 2>&1; then
    echo "fuzz $1: $(grep -o 'stat::number_of_executed_units: [0-9]*' "$build/fuzz-$1.log" | grep -o '[0-9]*$') executions, no crash"
  else
    echo "fuzz $1: FAILED, see $build/fuzz-$1.log and $build/fuzz-artifacts/$1/" >&2
    tail -n 40 "$build/fuzz-$1.log" >&2
    return 1
  fi
}
pids=()
for target in $targets; do
  run_one "$target" & pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then wait "${pids[0]}" || failed=1; pids=("${pids[@]:1}"); fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit $failed
