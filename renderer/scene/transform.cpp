#include "scene/transform.hpp"

#include <cmath>

#include "common/error.hpp"

namespace facet {

glm::dmat4 translate_rotate_scale(glm::dvec3 translate, glm::dvec3 rotate_deg, glm::dvec3 scale) {
  const glm::dvec3 a = glm::radians(rotate_deg);
  const double cx = std::cos(a.x), sx = std::sin(a.x);
  const double cy = std::cos(a.y), sy = std::sin(a.y);
  const double cz = std::cos(a.z), sz = std::sin(a.z);
  // glm matrices are column-major: m[column][row].
  const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  const glm::dmat3 linear = rz * ry * rx * glm::dmat3(scale.x, 0, 0, 0, scale.y, 0, 0, 0, scale.z);
  glm::dmat4 m(linear);
  m[3] = glm::dvec4(translate, 1.0);
  return m;
}

void transform_mesh(Mesh& mesh, const glm::dmat4& m) {
  const glm::dmat3 linear(m);
  const double det = glm::determinant(linear);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) throw Error("transform has a non-finite entry");
    }
  }
  // Relative to the scale of the matrix, so that tiny but regular transforms pass.
  const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  if (!(std::abs(det) > 1e-12 * scale) || !std::isfinite(det)) {
    throw Error("transform is singular (determinant " + std::to_string(det) + ")");
  }
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  const double handedness = det > 0.0 ? 1.0 : -1.0;

  for (glm::dvec3& p : mesh.positions) p = glm::dvec3(m * glm::dvec4(p, 1.0));
  for (glm::dvec3& n : mesh.normals) n = glm::normalize(normal_matrix * n);
  for (glm::dvec4& t : mesh.tangents) {
    t = glm::dvec4(glm::normalize(linear * glm::dvec3(t)), t.w * handedness);
  }
}

}  // namespace facet
