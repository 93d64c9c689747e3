#include "gpu/diffraction_domain.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "kernels/shared.hpp"
#include "scene/camera_frame.hpp"
#include "scene/plane_frame.hpp"

namespace facet::gpu {

namespace {

constexpr int kFilmSamples = 65;  // per film axis, corners included

using Pair = std::pair<glm::dvec3, glm::dvec3>;

std::vector<Camera> scene_cameras(const Scene& scene) {
  std::vector<Camera> cameras = {scene.camera};
  if (scene.camera_path)
    for (const CameraKey& key : scene.camera_path->keys) {
      Camera c = scene.camera;
      c.position = key.position;
      c.target = key.target;
      c.fov_y_deg = key.fov_y_deg;
      cameras.push_back(c);
    }
  return cameras;
}

// The lit pair of the ray from `origin` along `d` on `plane`, if it hits.
std::optional<Pair> plane_pair(const Scene& scene, const Plane& plane, const PlaneFrame& frame,
                               const glm::dvec3& origin, const glm::dvec3& d) {
  const double facing = glm::dot(d, frame.normal);
  if (facing == 0.0) return std::nullopt;
  const double t = glm::dot(plane.point - origin, frame.normal) / facing;
  if (!(t > 0.0)) return std::nullopt;
  const glm::dvec3 r = origin + t * d - plane.point;
  if (plane.size && (std::abs(glm::dot(r, frame.tangent)) > 0.5 * plane.size->x ||
                     std::abs(glm::dot(r, frame.bitangent)) > 0.5 * plane.size->y))
    return std::nullopt;
  const auto dirs = kernels::f64::diffraction_directions(frame.normal, frame.tangent, scene.light.direction, -d);
  if (!dirs.lit) return std::nullopt;
  return Pair{dirs.wi, dirs.wr};
}

glm::dvec3 uvw(const Pair& p) { return -(p.first + p.second); }

}  // namespace

diffraction::PreintegratedDomain diffraction_view_domain(const Scene& scene, uint32_t material) {
  const bool curved =
      std::any_of(scene.spheres.begin(), scene.spheres.end(),
                  [&](const Sphere& s) { return s.material == material; }) ||
      std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) { return m.material == material; });
  if (curved) return {glm::dvec2(-2.0), glm::dvec2(2.0), -2.0, 0.0};
  std::vector<Pair> pairs;
  double step = 0.0;  // largest |(u, v, w)| change between neighbouring film samples
  for (const Plane& plane : scene.planes) {
    if (plane.material != material) continue;
    const PlaneFrame frame = plane_frame(plane);
    for (const Camera& camera : scene_cameras(scene)) {
      const CameraFrame c = camera_frame(camera, camera.width, camera.height);
      std::vector<std::optional<Pair>> grid;
      for (int iy = 0; iy < kFilmSamples; ++iy)
        for (int ix = 0; ix < kFilmSamples; ++ix) {
          const glm::dvec2 ndc = glm::dvec2(ix, iy) * (2.0 / (kFilmSamples - 1)) - 1.0;
          grid.push_back(
              plane_pair(scene, plane, frame, c.origin, glm::normalize(c.forward + ndc.x * c.right - ndc.y * c.up)));
        }
      for (int iy = 0; iy < kFilmSamples; ++iy)
        for (int ix = 0; ix < kFilmSamples; ++ix) {
          const auto& here = grid[static_cast<size_t>(iy) * kFilmSamples + ix];
          if (!here) continue;
          pairs.push_back(*here);
          if (ix + 1 < kFilmSamples && grid[static_cast<size_t>(iy) * kFilmSamples + ix + 1])
            step =
                std::max(step, glm::length(uvw(*grid[static_cast<size_t>(iy) * kFilmSamples + ix + 1]) - uvw(*here)));
          if (iy + 1 < kFilmSamples && grid[static_cast<size_t>(iy + 1) * kFilmSamples + ix])
            step =
                std::max(step, glm::length(uvw(*grid[static_cast<size_t>(iy + 1) * kFilmSamples + ix]) - uvw(*here)));
        }
    }
  }
  if (pairs.empty()) return diffraction::domain_of_directions({{glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)}});
  diffraction::PreintegratedDomain d = diffraction::domain_of_directions(pairs);
  d.uv_min = glm::max(d.uv_min - step, glm::dvec2(-2.0));
  d.uv_max = glm::min(d.uv_max + step, glm::dvec2(2.0));
  d.w_min = std::max(d.w_min - step, -2.0);
  d.w_max = std::min(d.w_max + step, 0.0);
  return d;
}

}  // namespace facet::gpu
