#!/usr/bin/env bash
# A longer fuzzing run of one target (docs/hardening.md):
#   bash tools/fuzz_long.sh TARGET SECONDS [BUILD_DIR]      e.g. bash tools/fuzz_long.sh scene_json 600
# Needs the sanitizer+fuzz build (tools/test.sh makes it in build-asan). The corpus grows in
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
# The sanitizer options and suppressions are compiled into the program (tools/sanitizers/sanitizer_defaults.cpp).
exec "$program" "$corpus" "${seeds[@]}" -dict=fuzz/json.dict -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts/"
