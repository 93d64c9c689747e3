// How many MIP nodes the GPU height-field tracer (shaders/render/heightfield_trace.glsl) may visit per ray,
// so that the pass can refuse, in one line, a scene whose rays could pass lavapipe's loop limit
// (docs/microsurface_filtering.md, "Loop bound"). The tracer cuts every ray to the field's height range
// before it walks, so a ray's nodes are bounded by the length of that cut segment over the rectangle: short
// wherever the ray crosses the range steeply, the whole rectangle only for rays nearly parallel to it.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet::gpu {

// The heights of the field's vertices along its plane's normal, lowest and highest (bilinear cells stay within
// their corners').
glm::dvec2 heightfield_height_range(const MicrosurfaceMaterial& material);

// An upper bound on the MIP nodes one ray visits in the field of `material` tiled over a rectangle of
// `patch_size` (world units), where the ray's segment within the field's height range runs at most
// `path_texels` texels across the rectangle (infinity: anywhere across it).
std::int64_t heightfield_trace_nodes(const MicrosurfaceMaterial& material, glm::dvec2 patch_size, double path_texels);

// The longest segment, in world units across the plane, of a ray within the height range [z_lo, z_hi] of a
// field on `plane` (heights along its normal from `plane.point`), widened by the tracer's margin for origins
// up to `origin_height` from the plane: for rays from `origin` that reach the rectangle (camera rays), or in
// direction `direction` from anywhere within `origin_height` of the plane (shadow rays). Infinity where the
// ray can run parallel to the plane within the range.
double heightfield_camera_ray_path(const Plane& plane, double z_lo, double z_hi, glm::dvec3 origin);
double heightfield_directed_ray_path(const Plane& plane, double z_lo, double z_hi, glm::dvec3 direction,
                                     double origin_height);

// The nodes one shadow ray toward the light may visit in all of the scene's height fields, and one camera ray
// from `camera`.
std::int64_t heightfield_shadow_nodes(const Scene& scene);
std::int64_t heightfield_camera_nodes(const Scene& scene, glm::dvec3 camera);

}  // namespace facet::gpu
