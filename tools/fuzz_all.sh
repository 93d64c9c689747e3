#!/usr/bin/env bash
# Every fuzz target for SECONDS (default 30), two at a time on the 2 cores (docs/hardening.md):
#   bash tools/fuzz_all.sh [SECONDS] [BUILD_DIR]
# Needs the sanitizer+fuzz build that tools/test.sh makes in build-asan. Fails if any target finds a
# crash, a sanitizer report, a leak or a hang; the finding is in BUILD_DIR/fuzz-artifacts/TARGET/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
build=${2:-build-asan}
jobs=$(nproc)
targets=$(sed -n 's/^facet_add_fuzz_target(NAME \([a-z_]*\) .*/\1/p' fuzz/CMakeLists.txt)
run_one() {
  if bash tools/fuzz_long.sh "$1" "$seconds" "$build" > "$build/fuzz-$1.log" 2>&1; then
    local runs rate
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz-$1.log" | grep -o '[0-9]*$')
    rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$build/fuzz-$1.log" | grep -o '[0-9]*$')
    echo "fuzz $1: $runs executions in ${seconds} s ($rate/s), no finding"
  else
    echo "fuzz $1: FAILED, see $build/fuzz-$1.log and $build/fuzz-artifacts/$1/" >&2
    tail -n 40 "$build/fuzz-$1.log" >&2
    return 1
  fi
}
failed=0
pids=()
for target in $targets; do
  run_one "$target" & pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then wait "${pids[0]}" || failed=1; pids=("${pids[@]:1}"); fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit $failed
