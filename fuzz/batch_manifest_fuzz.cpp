// Fuzz target: a `facet batch` manifest (possibly left corrupt by another tool) through
// read_manifest.
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "batch/manifest.hpp"
#include "common/error.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".json");
  try {
    facet::batch::read_manifest(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
