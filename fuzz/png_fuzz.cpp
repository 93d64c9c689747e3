// Fuzz target: a PNG texture or height map through read_png.
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "fuzz_image_size.hpp"
#include "fuzz_input_file.hpp"
#include "image/png_io.hpp"

namespace {

// The size in the IHDR chunk, which a PNG must start with (after the 8-byte signature, the chunk's
// length and type): big-endian width and height at bytes 16 and 20.
bool skipped(const std::uint8_t* data, std::size_t size) {
  if (size < 24 || data[12] != 'I' || data[13] != 'H' || data[14] != 'D' || data[15] != 'R') return false;
  auto big_endian = [&](std::size_t at) {
    return std::int64_t{data[at]} << 24 | std::int64_t{data[at + 1]} << 16 | std::int64_t{data[at + 2]} << 8 |
           data[at + 3];
  };
  return facet::fuzz::legal_but_too_large_to_fuzz(big_endian(16), big_endian(20));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (facet::fuzz::kSkipCostlyInputs && skipped(data, size)) return 0;
  const facet::fuzz::FuzzInputFile input(data, size, ".png");
  try {
    facet::read_png(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
