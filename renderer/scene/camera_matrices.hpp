// The camera as the matrices compositors and pbrt-v4 users read from an EXR header (worldToCamera,
// worldToNDC), in pbrt-v4's conventions (ProjectiveCamera::InitMetadata, film.cpp):
//
// - Column vectors: p' = M p with p = (x, y, z, 1); the translation is in column 3. pbrt-v4 writes its
//   matrices into the EXR M44f element by element, so m[row][column] there is this M's, the transpose
//   of Imath's own row-vector habit.
// - Camera space: the eye at the origin, +z toward the target, +y up in the image, +x to the image's
//   right (left-handed, as pbrt's camera space is).
// - NDC = T(1/2) S(1/2) Perspective(fov, 1e-2, 1000) camera, homogeneous (divide by w = camera z):
//   pbrt's perspective maps the field of view of the image's shorter side onto [-1, 1], so the
//   image spans NDC x in [1/2 - a/2, 1/2 + a/2] (a = width / height >= 1) and y in [0, 1] (y up: the
//   top row is y = 1); a portrait image spans x in [0, 1] and y in [1/2 - 1/(2a), 1/2 + 1/(2a)].
//   The target is at NDC (1/2, 1/2); z grows from 0 at the near plane (1e-2) to 1 at the far (1000).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

glm::dmat4 world_to_camera(const Camera& camera);

// For a `width` x `height` image of `camera` (its fov_y is the vertical field of view).
glm::dmat4 world_to_ndc(const Camera& camera, int width, int height);

}  // namespace facet
