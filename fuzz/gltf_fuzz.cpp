// Fuzz target: a glTF 2.0 file through facet's mesh loader and its scene reader (binary .glb when the
// input starts with the glTF magic).
// A facet::Error is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception escaping) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/gltf_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const facet::fuzz::FuzzInputFile input(data, size, binary ? ".glb" : ".gltf");
  try {
    facet::load_gltf_meshes(input.path(), glm::dmat4(1.0), 0);
  } catch (const facet::Error&) {
  }
  try {
    facet::load_gltf_scene(input.path(), {});
  } catch (const facet::Error&) {
  }
  return 0;
}
