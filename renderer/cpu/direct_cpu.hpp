// The CPU twin of the GPU direct-lighting pass: the same primary rays and shading, in double, with
// Embree (through RayCaster) for meshes and the shared f64 kernels for everything else.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

// One primary ray through each pixel centre; parallel over rows (oneTBB).
Image render_direct_cpu(const Scene& scene, int width, int height);

}  // namespace facet::cpu
