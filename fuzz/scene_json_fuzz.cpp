// Fuzz target: a facet scene file (scenes/README.md) through load_scene, the path `facet render` reads.
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const facet::fuzz::FuzzInputFile input(data, size, ".json");
  try {
    facet::load_scene(input.path());
  } catch (const facet::Error&) {
  }
  return 0;
}
