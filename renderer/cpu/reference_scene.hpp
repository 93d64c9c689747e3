// The geometry the reference renderer traces: the macro scene through RayCaster (Embree + analytic
// planes and spheres, double) and every microsurface plane as its real displaced height field
// (HeightField: exact bilinear intersection, double), so masking and shadowing are traced.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/heightfield.hpp"
#include "cpu/ray_caster.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

struct SurfaceHit {
  double t;
  glm::dvec3 position;
  glm::dvec3 normal;  // shading normal, on the side the ray came from
  glm::dvec2 uv;      // macro hits: the object's uv
  uint32_t material;
  glm::dvec3 dpdu{0.0};  // macro hits: the tangent dp/du (RayCaster's Hit)
  // Microsurface hits only: the field's height z, slope ∇z, and the plane's tangent (for anisotropy).
  bool micro = false;
  double height = 0.0;
  glm::dvec2 slope{0.0};
  glm::dvec3 tangent{0.0};
  bool back_face = false;  // macro hits: as RayCaster's Hit
};

class ReferenceScene {
 public:
  // Keeps a reference to `scene` (materials); throws facet::Error as RayCaster and HeightField do.
  explicit ReferenceScene(const Scene& scene);

  // Nearest hit for t in (0, t_max) of o + t d, d unit.
  std::optional<SurfaceHit> intersect(glm::dvec3 o, glm::dvec3 d) const;
  bool occluded(glm::dvec3 o, glm::dvec3 d) const;

  // The origin of a shadow ray from `hit`: offset along the normal past rounding (docs/reference.md).
  glm::dvec3 shadow_origin(const SurfaceHit& hit) const;

 private:
  struct Patch {
    HeightField field;
    uint32_t material;
  };
  static Scene without_microsurfaces(const Scene& scene);

  const Scene& scene_;
  Scene macro_;       // the scene without its microsurface planes
  RayCaster caster_;  // over macro_
  std::vector<Patch> patches_;
};

}  // namespace facet::cpu
