// Image sizes the fuzz targets skip. A valid file may declare up to 16384 x 16384 pixels
// (kMaxImageFileSide) and compress them into a few kilobytes: correct to read, but up to
// gigabytes and seconds per input for the fuzzer, and the same decoding code as a small image.
// Inputs declaring a legal size above kFuzzPixels are therefore skipped; sizes outside the legal
// range still reach the readers (their refusal is what is fuzzed); a large legal image is read by
// Faults.FramesBeyondTheStorageBufferRangeRenderWhole (2900 x 2900 EXR).
#pragma once

#include <cstdint>

#include "image/image.hpp"

namespace facet::fuzz {

// Only the libFuzzer programs skip (libfuzzer_mode.cpp); the replay programs (ctest's fuzz_replay.*,
// replay_main.cpp) run every corpus and regression input through the readers, large ones included.
extern const bool kSkipCostlyInputs;

inline constexpr std::int64_t kFuzzPixels = std::int64_t{1} << 16;  // 256 x 256

inline bool legal_but_too_large_to_fuzz(std::int64_t width, std::int64_t height) {
  const bool legal = width >= 1 && height >= 1 && width <= kMaxImageFileSide && height <= kMaxImageFileSide;
  return legal && width * height > kFuzzPixels;
}

}  // namespace facet::fuzz
