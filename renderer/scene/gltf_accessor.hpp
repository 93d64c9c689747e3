// Bounds-checked reading of glTF accessors into doubles.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace facet {

struct AccessorData {
  std::vector<double> values;  // count * components, element-major
  size_t count = 0;
  int components = 0;
};

// Reads accessor `index`, which must have glTF type `type` (TINYGLTF_TYPE_*). Normalised
// integer components are mapped to [0, 1] / [-1, 1] as glTF 2.0 section 3.11 prescribes.
// With `integers_only`, float components are rejected (indices). Throws facet::Error
// naming `what` ("quad primitive 0 POSITION") if the accessor or its buffer view is missing,
// sparse, empty, or reaches outside its buffer.
AccessorData read_accessor(const tinygltf::Model& model, int index, int type, bool integers_only,
                           const std::string& what);

}  // namespace facet
