// Nearest-hit and occlusion queries against a whole scene on the CPU, in double precision.
//
// Meshes go through Embree 3 (float), and each mesh hit is then re-intersected in double
// against its triangle; planes and spheres use the shared analytic kernels
// (shaders/lib/analytic_intersect.glsl, f64 twin). Conventions (docs/ray_caster.md):
// - a ray is o + t d with unit d; hits count for t in (0, t_max); callers offset the
//   origin of secondary rays themselves;
// - geometric_normal faces the ray's side (dot(geometric_normal, d) <= 0);
// - shading_normal is the interpolated vertex normal (the geometric one without vertex
//   normals), turned into the hemisphere of geometric_normal;
// - non-finite o, d or t_max give no hit.
// Queries are const and thread-safe; the Scene must outlive the caster. The constructor
// throws facet::Error for meshes that break check_mesh (scene/mesh_check.hpp).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/plane_frame.hpp"
#include "scene/scene.hpp"

namespace facet {

struct Hit {
  double t;
  glm::dvec3 position, geometric_normal, shading_normal;
  glm::dvec2 uv;
  uint32_t material;
  glm::dvec3 dpdu{0.0};  // dp/du of the uv parameterisation, as render/trace.glsl's surface_uv (0: degenerate)
  // shading_normal was turned: the ray met the side opposite the scene's normal (a grating seen from below,
  // diffraction_frame.glsl)
  bool back_face = false;
};

class RayCaster {
 public:
  explicit RayCaster(const Scene& scene);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  std::optional<Hit> intersect(glm::dvec3 o, glm::dvec3 d,
                               double t_max = std::numeric_limits<double>::infinity()) const;
  bool occluded(glm::dvec3 o, glm::dvec3 d, double t_max) const;

 private:
  struct Embree;
  const Scene& scene_;
  std::vector<PlaneFrame> plane_frames_;  // parallel to scene_.planes: the uv axes, computed once
  std::unique_ptr<Embree> embree_;
};

}  // namespace facet
