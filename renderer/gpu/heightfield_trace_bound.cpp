#include "gpu/heightfield_trace_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include "scene/plane_frame.hpp"

namespace facet::gpu {

glm::dvec2 heightfield_height_range(const MicrosurfaceMaterial& m) {
  const auto [lo, hi] = std::minmax_element(m.heights->values.begin(), m.heights->values.end());
  const double a = m.height_scale * *lo, b = m.height_scale * *hi;
  return {std::min(a, b), std::max(a, b)};
}

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The tracer widens the field's height range by 1e-5 (|o.z| + |z_lo - z_0| + |z_hi - z_0|), z_0 the
// stored heights' mean (render/heightfield_trace.glsl): at most this, with room for float rounding.
double tracer_margin(double origin_height, double z_lo, double z_hi) {
  return 2e-5 * (origin_height + 4.0 * (std::abs(z_lo) + std::abs(z_hi)));
}

double height_over(const Plane& plane, glm::dvec3 x) {
  return std::abs(glm::dot(x - plane.point, plane_frame(plane).normal));
}

// How far from `field`'s plane a shadow ray may start: at a point of the scene's geometry (hits are offset by
// 1e-4 max(1, |p|) along their normal, render/direct_pass.glsl). Infinite where an infinite plane not parallel to
// the field's reaches every height.
double shadow_origin_height(const Scene& scene, const Plane& field) {
  const glm::dvec3 n = plane_frame(field).normal;
  double height = 0.0, reach = 1.0;  // reach: the largest |p| of a finite origin
  const auto take = [&](glm::dvec3 x, double extra) {
    height = std::max(height, height_over(field, x) + extra);
    reach = std::max(reach, glm::length(x) + extra);
  };
  for (const Sphere& s : scene.spheres) take(s.center, s.radius);
  for (const Mesh& m : scene.meshes)
    for (const glm::dvec3& p : m.positions) take(p, 0.0);
  for (const Plane& p : scene.planes) {
    if (p.size) {
      double relief = 0.0;
      if (const auto* m = std::get_if<MicrosurfaceMaterial>(&scene.materials[p.material])) {
        const glm::dvec2 z = heightfield_height_range(*m);
        relief = std::max(std::abs(z.x), std::abs(z.y));
      }
      for (const glm::dvec3& c : plane_rectangle_corners(p)) take(c, relief);
    } else if (glm::length(glm::cross(plane_frame(p).normal, n)) > 1e-12) {
      return kUnbounded;
    }
  }
  // An infinite plane parallel to the field's: a point of it whose ray toward the light meets the field's
  // range lies within (offset + relief) / tan(elevation) of the rectangle, so |p| and with it the offset of its
  // hits along the normal, 1e-4 |p|, are bounded by the reach of the farthest such point.
  const glm::dvec3 l = glm::normalize(scene.light.direction);
  const double sine = std::abs(glm::dot(l, n)), tangent = sine / std::sqrt(std::max(1.0 - sine * sine, 1e-300));
  const glm::dvec2 z = heightfield_height_range(std::get<MicrosurfaceMaterial>(scene.materials[field.material]));
  const double field_relief = std::max(std::abs(z.x), std::abs(z.y));
  for (const Plane& p : scene.planes) {
    if (p.size) continue;
    if (tangent <= 0.0) return kUnbounded;
    const double offset = height_over(field, p.point);
    const double far = reach + glm::length(*field.size) + (offset + field_relief) / tangent + glm::length(p.point);
    height = std::max(height, offset + 1e-4 * far);
  }
  return height * (1.0 + 1e-4) + 1e-4 * reach;
}

// The nodes one ray may visit in all of the scene's height fields, its path through each (world units across the
// plane) given by path(plane, the field's height range).
template <class Path>
std::int64_t nodes_over_fields(const Scene& scene, Path path) {
  std::int64_t nodes = 0;
  for (const Plane& plane : scene.planes) {
    const auto* m = std::get_if<MicrosurfaceMaterial>(&scene.materials[plane.material]);
    if (!m || !plane.size) continue;
    nodes += heightfield_trace_nodes(*m, *plane.size, path(plane, heightfield_height_range(*m)) / m->texel_size);
  }
  return nodes;
}

}  // namespace

std::int64_t heightfield_trace_nodes(const MicrosurfaceMaterial& material, glm::dvec2 patch_size, double path_texels) {
  const std::int64_t w = material.heights->width, h = material.heights->height;
  const std::int64_t tiles_x =
      static_cast<std::int64_t>(std::ceil(patch_size.x / (static_cast<double>(w) * material.texel_size)));
  const std::int64_t tiles_y =
      static_cast<std::int64_t>(std::ceil(patch_size.y / (static_cast<double>(h) * material.texel_size)));
  // The traversal (render/heightfield_trace.glsl) takes one step per node it enters, enters each node at
  // most once, and enters only nodes its segment within the height range passes through: at level l, one
  // more than the node faces (a level's faces within each tile, and the tiles' faces) the segment crosses.
  // Over the whole rectangle's C x R nodes of a level that is at most C + R - 1; a segment of length L
  // (texels) at angle phi crosses at most L|cos phi| / 2^l + 2 (L|cos phi| / w + 2) faces across x and as
  // many across y (|cos phi| + |sin phi| <= sqrt 2).
  const double shortest_tile = static_cast<double>(std::min(w, h));
  std::int64_t nodes = 0;
  for (int l = 0; (std::int64_t{1} << l) < 2 * std::max(w, h); ++l) {
    const std::int64_t columns = tiles_x * ((w + (std::int64_t{1} << l) - 1) >> l);
    const std::int64_t rows = tiles_y * ((h + (std::int64_t{1} << l) - 1) >> l);
    std::int64_t level = columns + rows - 1;
    if (std::isfinite(path_texels)) {
      const double faces = std::sqrt(2.0) * path_texels * (std::ldexp(1.0, -l) + 2.0 / shortest_tile) + 8.0;
      if (faces < static_cast<double>(level)) level = 1 + static_cast<std::int64_t>(std::ceil(faces));
    }
    nodes += level;
  }
  return nodes;
}

double heightfield_camera_ray_path(const Plane& plane, double z_lo, double z_hi, glm::dvec3 origin) {
  const glm::dvec3 n = plane_frame(plane).normal;
  const double height = glm::dot(origin - plane.point, n);
  const double margin = tracer_margin(std::abs(height), z_lo, z_hi);
  const double lo = z_lo - margin, hi = z_hi + margin;
  const double gap = height > hi ? height - hi : lo - height;  // to the range's near side
  if (!(gap > 0.0)) return kUnbounded;
  // A ray that meets the range over the rectangle enters it at most the farthest corner's distance across
  // the plane from the origin, so it descends by at least gap over that distance, and crosses the range's
  // thickness over at most thickness / gap times it.
  double farthest = 0.0;
  for (const glm::dvec3& c : plane_rectangle_corners(plane)) {
    const glm::dvec3 rel = c - origin;
    farthest = std::max(farthest, glm::length(rel - glm::dot(rel, n) * n));
  }
  return (hi - lo) * farthest / gap * (1.0 + 1e-3);
}

double heightfield_directed_ray_path(const Plane& plane, double z_lo, double z_hi, glm::dvec3 direction,
                                     double origin_height) {
  if (!std::isfinite(origin_height)) return kUnbounded;
  const glm::dvec3 d = glm::normalize(direction);
  const double sine = std::abs(glm::dot(d, plane_frame(plane).normal));
  if (!(sine > 0.0)) return kUnbounded;
  const double margin = tracer_margin(origin_height, z_lo, z_hi);
  return (z_hi - z_lo + 2.0 * margin) * std::sqrt(std::max(1.0 - sine * sine, 0.0)) / sine * (1.0 + 1e-3);
}

std::int64_t heightfield_shadow_nodes(const Scene& scene) {
  return nodes_over_fields(scene, [&](const Plane& plane, glm::dvec2 z) {
    return heightfield_directed_ray_path(plane, z.x, z.y, scene.light.direction, shadow_origin_height(scene, plane));
  });
}

std::int64_t heightfield_camera_nodes(const Scene& scene, glm::dvec3 camera) {
  return nodes_over_fields(
      scene, [&](const Plane& plane, glm::dvec2 z) { return heightfield_camera_ray_path(plane, z.x, z.y, camera); });
}

}  // namespace facet::gpu
