// The diffracted light of "diffraction" materials on the CPU, in double (docs/diffraction.md,
// "Rendering"): the Taylor twin of the GPU's spectral loop for the direct CPU pass, and the
// exact transform (Chebyshev-interpolated exact bins, no Taylor series) for the reference.
// The Lambertian base of the material is shade_macro_surface's; this adds the iridescence.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/chebyshev_transform.hpp"
#include "diffraction/prepared_diffraction.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

class DiffractionShading {
 public:
  enum class Transform { Taylor, Exact };

  // Builds what every diffraction material of `scene` needs. Exact keeps window weights down to
  // kExactWindowTolerance (the Taylor path stops at the material's tolerance).
  DiffractionShading(const Scene& scene, Transform transform, const diffraction::DiffractionSettings& settings = {});
  // The wavelength samples of radiance() are the material's (prepared_diffraction.hpp) either way.
  static constexpr double kExactWindowTolerance = 1e-10;

  bool handles(uint32_t material) const { return material < entries_.size() && entries_[material] != nullptr; }

  // Radiance of the diffracted light, summed over the material's wavelength samples
  // (diffraction_frame.glsl: rgb(sum BRDF xyz_weight) E cos_i visibility). n: shading normal facing
  // the viewer; back_face: n is the scene's normal turned (diffraction_directions_seen's `below`); dpdu:
  // the surface tangent; v: toward the viewer.
  glm::dvec3 radiance(uint32_t material, glm::dvec3 n, bool back_face, glm::dvec3 dpdu, glm::dvec3 v,
                      double visibility) const;

  // The same at one wavelength 360 + 470 u nm (u in [0, 1)), weighted by 470 nm xyz_density: an
  // unbiased one-sample estimate of radiance()'s integral, for the reference's per-sample wavelengths.
  glm::dvec3 radiance_at(uint32_t material, glm::dvec3 n, bool back_face, glm::dvec3 dpdu, glm::dvec3 v,
                         double visibility, double u) const;

 private:
  struct Entry {
    const DiffractionMaterial* material;
    diffraction::PreparedDiffraction prepared;
    std::unique_ptr<diffraction::ChebyshevTransform> exact;  // Transform::Exact only
  };
  double brdf(const Entry& e, glm::dvec3 wi, glm::dvec3 wr, double lambda_nm) const;

  const Scene& scene_;
  std::vector<std::unique_ptr<Entry>> entries_;  // per scene material; null unless diffraction
};

}  // namespace facet::cpu
