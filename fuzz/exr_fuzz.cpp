// Fuzz target: an OpenEXR file through every facet reader of EXR input: frames (read_exr, as
// `facet compare` reads them), scalar textures (read_exr_scalar) and height fields
// (read_scalar_field_exr).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "assets/scalar_field.hpp"
#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "image/exr_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".exr");
  try {
    facet::ExrMetadata metadata;
    facet::read_exr(input.path(), &metadata);
  } catch (const facet::Error&) {
  }
  try {
    facet::read_exr_scalar(input.path(), "Y");
  } catch (const facet::Error&) {
  }
  try {
    facet::assets::read_scalar_field_exr(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
