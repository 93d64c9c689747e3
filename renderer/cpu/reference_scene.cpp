#include "cpu/reference_scene.hpp"

#include <cmath>
#include <limits>
#include <variant>

#include "scene/plane_frame.hpp"

namespace facet::cpu {

namespace {

bool is_microsurface(const Scene& scene, uint32_t material) {
  return std::holds_alternative<MicrosurfaceMaterial>(scene.materials[material]);
}

HeightField make_height_field(const Plane& plane, const MicrosurfaceMaterial& m) {
  const PlaneFrame frame = plane_frame(plane);
  HeightFieldGrid grid{m.heights->width, m.heights->height, m.heights->values, m.texel_size, m.height_scale};
  HeightFieldPlacement placement;
  // The rectangle is centred at plane.point; the field starts at its (−w/2, −h/2) corner.
  placement.origin = plane.point - 0.5 * plane.size->x * frame.tangent - 0.5 * plane.size->y * frame.bitangent;
  placement.tangent = frame.tangent;
  placement.bitangent = frame.bitangent;
  placement.normal = frame.normal;
  placement.size = *plane.size;
  return HeightField(std::move(grid), placement);
}

}  // namespace

Scene ReferenceScene::without_microsurfaces(const Scene& scene) {
  Scene macro = scene;
  std::erase_if(macro.planes, [&](const Plane& p) { return is_microsurface(scene, p.material); });
  return macro;
}

ReferenceScene::ReferenceScene(const Scene& scene)
    : scene_(scene), macro_(without_microsurfaces(scene)), caster_(macro_) {
  for (const Plane& p : scene.planes) {
    if (is_microsurface(scene, p.material))
      patches_.push_back(
          {make_height_field(p, std::get<MicrosurfaceMaterial>(scene.materials[p.material])), p.material});
  }
}

std::optional<SurfaceHit> ReferenceScene::intersect(glm::dvec3 o, glm::dvec3 d) const {
  std::optional<SurfaceHit> best;
  if (const auto hit = caster_.intersect(o, d)) {
    best = SurfaceHit{hit->t, hit->position, hit->shading_normal, hit->uv, hit->material, hit->dpdu};
    best->back_face = hit->back_face;
  }
  for (const Patch& patch : patches_) {
    const auto hit = patch.field.intersect(o, d, best ? best->t : std::numeric_limits<double>::infinity());
    if (!hit) continue;
    // The field's normal is the upper side's; turn it toward the ray as RayCaster does.
    const glm::dvec3 n = glm::dot(hit->normal, d) > 0.0 ? -hit->normal : hit->normal;
    best = SurfaceHit{hit->t,          hit->position, n,           hit->uv,    patch.material,
                      glm::dvec3(0.0), true,          hit->height, hit->slope, patch.field.placement().tangent};
  }
  return best;
}

bool ReferenceScene::occluded(glm::dvec3 o, glm::dvec3 d) const {
  const double infinity = std::numeric_limits<double>::infinity();
  if (caster_.occluded(o, d, infinity)) return true;
  for (const Patch& patch : patches_)
    if (patch.field.occluded(o, d, infinity)) return true;
  return false;
}

glm::dvec3 ReferenceScene::shadow_origin(const SurfaceHit& hit) const {
  const double scale = std::max(1.0, glm::length(hit.position));
  if (!hit.micro) return hit.position + hit.normal * (1e-4 * scale);  // as the direct pass (render/direct_pass.glsl)
  // Height fields are intersected exactly in double: a few hundred ulp of the position clear the
  // surface, and 1e-6 texel keeps the offset far below the field's detail.
  const double texel = std::get<MicrosurfaceMaterial>(scene_.materials[hit.material]).texel_size;
  return hit.position + hit.normal * (1e-12 * scale + 1e-6 * texel);
}

}  // namespace facet::cpu
