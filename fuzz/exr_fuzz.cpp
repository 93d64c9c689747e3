// Fuzz target: an OpenEXR file through every facet reader of EXR input: frames (read_exr, as
// `facet compare` reads them), scalar textures (read_exr_scalar) and height fields
// (read_scalar_field_exr).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "assets/scalar_field.hpp"
#include "common/error.hpp"
#include "fuzz_image_size.hpp"
#include "fuzz_input_file.hpp"
#include "image/exr_header_check.hpp"
#include "image/exr_io.hpp"

namespace {

std::int64_t little_endian32(const std::uint8_t* p) {
  return static_cast<std::int32_t>(std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
                                   std::uint32_t{p[3]} << 24);
}

// True if the data window is a legal size above kFuzzPixels. (Attributes that claim more than the
// file holds are refused by read_exr itself before any allocation: image/exr_header_check.hpp.)
bool skipped(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  bool large = false;
  facet::walk_exr_headers(in, [&](const facet::ExrAttribute& a) {
    if (a.size > size - std::min<std::uint64_t>(a.offset, size)) return false;  // left to read_exr
    if (a.name != "dataWindow" || a.size != 16) return true;
    const std::uint8_t* box = data + a.offset;  // xMin, yMin, xMax, yMax
    large = facet::fuzz::legal_but_too_large_to_fuzz(little_endian32(box + 8) - little_endian32(box) + 1,
                                                     little_endian32(box + 12) - little_endian32(box + 4) + 1);
    return false;
  });
  return large;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (facet::fuzz::kSkipCostlyInputs && skipped(data, size)) return 0;
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
