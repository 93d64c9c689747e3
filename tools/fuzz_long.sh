#!/usr/bin/env bash
# A longer fuzzing run of one target (docs/hardening.md):
#   bash tools/fuzz_long.sh TARGET SECONDS [BUILD_DIR]      e.g. bash tools/fuzz_long.sh scene_json 600
# Needs the sanitizer+fuzz build (tools/test_hardening.sh makes it in build-asan). The corpus grows in
# BUILD_DIR/fuzz-corpus/TARGET (seeded from fuzz/corpus and fuzz/regressions, which it never writes);
# crashes, hangs (> 10 s per input) and out-of-memory inputs land in BUILD_DIR/fuzz-artifacts/TARGET/.
# After fixing one, copy it into fuzz/regressions/TARGET/ so that ctest replays it in every build.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: fuzz_long.sh TARGET SECONDS [BUILD_DIR]}
seconds=${2:?usage: fuzz_long.sh TARGET SECONDS [BUILD_DIR]}
build=${3:-build-asan}
program="$build/fuzz/fuzz_$target"
[ -x "$program" ] || { echo "facet: error: $program not built (configure with -DFACET_FUZZ=ON)" >&2; exit 1; }
corpus="$build/fuzz-corpus/$target"
artifacts="$build/fuzz-artifacts/$target"
mkdir -p "$corpus" "$artifacts"
seeds=()
for dir in "fuzz/corpus/$target" "fuzz/regressions/$target"; do [ -d "$dir" ] && seeds+=("$dir"); done
# The sanitizer options of the test suite (cmake/FacetSanitize.cmake), so a report is a crash here too.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$PWD/tools/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$PWD/tools/sanitizers/ubsan.supp:print_stacktrace=1:halt_on_error=1"
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer-16 || command -v llvm-symbolizer-14 || true)}
exec "$program" "$corpus" "${seeds[@]}" -dict=fuzz/json.dict -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts/"
