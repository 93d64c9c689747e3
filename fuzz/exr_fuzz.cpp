// Fuzz target: an OpenEXR file through every facet reader of EXR input: frames (read_exr, as
// `facet compare` reads them), scalar textures (read_exr_scalar) and height fields
// (read_scalar_field_exr).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "assets/scalar_field.hpp"
#include "common/error.hpp"
#include "fuzz_image_size.hpp"
#include "fuzz_input_file.hpp"
#include "image/exr_io.hpp"

namespace {

std::int64_t little_endian32(const std::uint8_t* p) {
  return static_cast<std::int32_t>(std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
                                   std::uint32_t{p[3]} << 24);
}

// Walks the first header's attributes (name\0 type\0 int32 size, data; an empty name ends it) to
// the data window, and skips the input if that is a legal size above kFuzzPixels. (Attributes that
// claim more than the file holds are refused by read_exr itself before any allocation:
// image/exr_header_check.hpp.)
bool skipped(const std::uint8_t* data, std::size_t size) {
  std::size_t at = 8;  // magic number and version
  while (at < size) {
    const auto* name_end = static_cast<const std::uint8_t*>(std::memchr(data + at, 0, size - at));
    if (name_end == nullptr || name_end == data + at) return false;  // truncated, or the end of the header
    const std::string name(reinterpret_cast<const char*>(data + at), name_end - (data + at));
    at = name_end - data + 1;
    const auto* type_end = static_cast<const std::uint8_t*>(std::memchr(data + at, 0, size - at));
    if (type_end == nullptr || size - (type_end - data + 1) < 4) return false;
    at = type_end - data + 1;
    const std::int64_t declared = little_endian32(data + at);
    at += 4;
    if (declared < 0 || declared > static_cast<std::int64_t>(size - at)) return false;
    if (name == "dataWindow" && declared == 16) {
      const std::int64_t width = little_endian32(data + at + 8) - little_endian32(data + at) + 1;
      const std::int64_t height = little_endian32(data + at + 12) - little_endian32(data + at + 4) + 1;
      return facet::fuzz::legal_but_too_large_to_fuzz(width, height);
    }
    at += static_cast<std::size_t>(declared);
  }
  return false;
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
