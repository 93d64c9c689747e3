// Fuzz target: a Gwyddion Simple Field (AFM) height map through read_gsf.
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "scene/grating/gsf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".gsf");
  try {
    facet::diffraction::read_gsf(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
