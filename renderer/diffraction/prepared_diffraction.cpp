#include "diffraction/prepared_diffraction.hpp"

#include <string>
#include <variant>

#include "common/error.hpp"
#include "diffraction/cie_tables.hpp"

namespace facet::diffraction {

namespace {
constexpr int kMaxWavelengths = 4096;
}

WavelengthSamples material_wavelengths(const DiffractionMaterial& material, const SpectralTables& tables,
                                       const DiffractionSettings& settings) {
  const int count = settings.wavelengths > 0 ? settings.wavelengths : material.wavelengths;
  if (count == 0) return diffraction_wavelength_samples(tables, material.tolerance, material.illuminant);
  if (count < 2 || count > kMaxWavelengths)
    throw Error("diffraction: the wavelength count must lie in [2, " + std::to_string(kMaxWavelengths) + "]");
  return wavelength_samples((kCieLambdaMaxNm - kCieLambdaMinNm) / (count - 1), material.illuminant);
}

PreparedDiffraction prepare_diffraction(const DiffractionMaterial& material, const DiffractionSettings& settings) {
  TableRange range;
  range.lambda_min_nm = kCieLambdaMinNm;
  range.lambda_max_nm = kCieLambdaMaxNm;
  range.tolerance = material.tolerance;
  range.terms = settings.taylor > 0 ? settings.taylor : material.taylor;
  PreparedDiffraction p{build_spectral_tables(*material.grating, range), {}};
  p.samples = material_wavelengths(material, p.tables, settings);
  return p;
}

std::vector<std::optional<PreparedDiffraction>> prepare_scene_diffraction(const Scene& scene,
                                                                          const DiffractionSettings& settings) {
  std::vector<std::optional<PreparedDiffraction>> prepared(scene.materials.size());
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (const auto* m = std::get_if<DiffractionMaterial>(&scene.materials[i]))
      prepared[i] = prepare_diffraction(*m, settings);
  return prepared;
}

}  // namespace facet::diffraction
