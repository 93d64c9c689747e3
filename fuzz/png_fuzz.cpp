// Fuzz target: a PNG texture or height map through read_png.
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "image/png_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".png");
  try {
    facet::read_png(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
