#include "scene/mesh_check.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"

namespace facet {

void check_mesh(const Mesh& mesh) {
  const auto fail = [&](const std::string& why) { throw Error("mesh " + mesh.name + ": " + why); };
  const size_t n = mesh.positions.size();
  if (mesh.indices.size() % 3 != 0) fail("the index count is not a multiple of 3");
  for (uint32_t i : mesh.indices) {
    if (i >= n) fail("index " + std::to_string(i) + " is outside [0, " + std::to_string(n) + ")");
  }
  if (!mesh.normals.empty() && mesh.normals.size() != n) fail("normals and positions differ in count");
  if (!mesh.uvs.empty() && mesh.uvs.size() != n) fail("uvs and positions differ in count");
  if (!mesh.tangents.empty() && (mesh.tangents.size() != n || mesh.normals.empty())) {
    fail("tangents need one per vertex and normals");
  }
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  for (const glm::dvec3& p : mesh.positions) {
    for (int k = 0; k < 3; ++k) {
      if (!(std::abs(p[k]) <= kFloatMax)) fail("a position is not finite in float precision");
    }
  }
}

}  // namespace facet
