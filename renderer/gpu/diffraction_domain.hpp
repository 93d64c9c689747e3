// The directions under which a scene shows a diffraction material, for the tables of the
// `preintegrated` method (docs/diffraction_fast_paths.md, "Rendering": the scene's domain).
#pragma once

#include <cstdint>

#include "diffraction/preintegrated_tables.hpp"
#include "scene/scene.hpp"

namespace facet::gpu {

// The (u, v) box and w range of every (light, view) pair on the objects of scene material
// `material`: on planes, sampled from the camera's rays over the whole film (the scene's camera and
// every key of its camera path) against the plane, widened by the largest step between neighbouring
// samples so that the rays between samples stay inside; on spheres and meshes, whose normals take
// every direction, the whole hemisphere of both directions. A material the camera never sees lit
// gets the one-point domain of normal incidence (its tables are never read).
diffraction::PreintegratedDomain diffraction_view_domain(const Scene& scene, uint32_t material);

}  // namespace facet::gpu
