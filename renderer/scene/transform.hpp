// Affine transforms applied to meshes: the scene file's object transform and glTF node transforms.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

// M = T * Rz * Ry * Rx * S: scale first, then rotate about x, y, z (degrees), then translate.
glm::dmat4 translate_rotate_scale(glm::dvec3 translate, glm::dvec3 rotate_deg, glm::dvec3 scale);

// Maps a mesh to another frame: positions by M, normals by the inverse transpose of M's
// linear part (renormalised), tangent directions by M (renormalised) with the handedness
// w multiplied by sign(det M) so that w * cross(n, t) stays the image of the bitangent.
// Throws facet::Error if M is not finite or its linear part is singular.
void transform_mesh(Mesh& mesh, const glm::dmat4& m);

}  // namespace facet
