// Fuzz target: a grating's JSON text through parse_grating (the `--grating` argument of
// `facet eval diffraction` and the "grating" object of a diffraction material).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "scene/grating/grating.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Text only: a string that is not JSON is taken as a file path, and the fuzzer must not open files.
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text[first] != '{') return 0;
  try {
    facet::diffraction::parse_grating(text);
  } catch (const facet::Error&) {
  }
  return 0;
}
