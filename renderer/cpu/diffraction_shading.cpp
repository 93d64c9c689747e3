#include "cpu/diffraction_shading.hpp"

#include <variant>

#include "diffraction/cie_tables.hpp"
#include "diffraction/diffraction_eval.hpp"
#include "kernels/shared.hpp"

namespace facet::cpu {

namespace k = kernels::f64;

namespace {

// The exact path needs no Taylor terms, only the band, the units and a window kept to a tighter
// tolerance; its wavelength samples (for radiance()) are the material's.
diffraction::PreparedDiffraction exact_tables(const DiffractionMaterial& m, const diffraction::DiffractionSettings& s) {
  diffraction::TableRange range;
  range.lambda_min_nm = diffraction::kCieLambdaMinNm;
  range.lambda_max_nm = diffraction::kCieLambdaMaxNm;
  range.tolerance = DiffractionShading::kExactWindowTolerance;
  range.terms = 1;
  diffraction::PreparedDiffraction p{diffraction::build_spectral_tables(*m.grating, range), {}};
  p.samples = diffraction::material_wavelengths(m, p.tables, s);
  return p;
}

}  // namespace

DiffractionShading::DiffractionShading(const Scene& scene, Transform transform,
                                       const diffraction::DiffractionSettings& settings)
    : scene_(scene), entries_(scene.materials.size()) {
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const auto* m = std::get_if<DiffractionMaterial>(&scene.materials[i]);
    if (m == nullptr) continue;
    if (transform == Transform::Taylor) {
      entries_[i] = std::make_unique<Entry>(Entry{m, diffraction::prepare_diffraction(*m, settings), nullptr});
    } else {
      entries_[i] = std::make_unique<Entry>(Entry{m, exact_tables(*m, settings), nullptr});
      entries_[i]->exact = std::make_unique<diffraction::ChebyshevTransform>(*m->grating, entries_[i]->prepared.tables);
    }
  }
}

double DiffractionShading::brdf(const Entry& e, glm::dvec3 wi, glm::dvec3 wr, double lambda_nm) const {
  const diffraction::DiffractionQuery q{wi, wr, lambda_nm};
  return e.exact ? e.exact->evaluate(q).brdf : diffraction::evaluate_taylor(e.prepared.tables, q).brdf;
}

glm::dvec3 DiffractionShading::radiance(uint32_t material, glm::dvec3 n, bool back_face, glm::dvec3 dpdu, glm::dvec3 v,
                                        double visibility) const {
  const Entry& e = *entries_[material];
  const auto d = k::diffraction_directions_seen(n, dpdu, scene_.light.direction, v, back_face);
  if (!d.lit || visibility == 0.0) return glm::dvec3(0.0);
  const diffraction::WavelengthSamples& s = e.prepared.samples;
  glm::dvec3 xyz(0.0);
  for (size_t i = 0; i < s.lambda_nm.size(); ++i) xyz += brdf(e, d.wi, d.wr, s.lambda_nm[i]) * s.xyz_weight[i];
  return k::diffraction_radiance(xyz, d.wi.z, scene_.light.irradiance, visibility);
}

glm::dvec3 DiffractionShading::radiance_at(uint32_t material, glm::dvec3 n, bool back_face, glm::dvec3 dpdu,
                                           glm::dvec3 v, double visibility, double u) const {
  const Entry& e = *entries_[material];
  const auto d = k::diffraction_directions_seen(n, dpdu, scene_.light.direction, v, back_face);
  if (!d.lit || visibility == 0.0) return glm::dvec3(0.0);
  const double span = diffraction::kCieLambdaMaxNm - diffraction::kCieLambdaMinNm;
  const double lambda = diffraction::kCieLambdaMinNm + span * u;
  const glm::dvec3 xyz = brdf(e, d.wi, d.wr, lambda) * span * diffraction::xyz_density(lambda, e.material->illuminant);
  return k::diffraction_radiance(xyz, d.wi.z, scene_.light.irradiance, visibility);
}

}  // namespace facet::cpu
