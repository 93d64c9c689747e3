// Fuzz target: a `facet batch` job file through load_job (scenes globs, methods, frames, output
// pattern, resolution, manifest).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "batch/job.hpp"
#include "common/error.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".json");
  try {
    facet::batch::load_job(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
