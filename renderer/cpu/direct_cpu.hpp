// The CPU twin of the GPU direct-lighting pass: the same primary rays and shading, in double, with
// Embree (through RayCaster) for meshes and the shared f64 kernels for everything else.
#pragma once

#include "cpu/diffraction_shading.hpp"
#include "diffraction/prepared_diffraction.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

// One primary ray through each pixel centre; parallel over rows (oneTBB). Diffraction materials
// use the Taylor tables and wavelength samples the GPU uses (`diffraction` overrides their counts),
// or with Transform::Exact the exact transform at those wavelengths (the GPU's own rays, without
// its Taylor error: what the benchmark measures the GPU's settings against).
Image render_direct_cpu(const Scene& scene, int width, int height,
                        const diffraction::DiffractionSettings& diffraction = {},
                        DiffractionShading::Transform transform = DiffractionShading::Transform::Taylor);

}  // namespace facet::cpu
