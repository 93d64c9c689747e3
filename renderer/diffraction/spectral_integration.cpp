#include "diffraction/spectral_integration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/error.hpp"
#include "diffraction/cie_tables.hpp"
#include "kernels/shared.hpp"

namespace facet::diffraction {

namespace {

double light_power(Illuminant light, double lambda_nm) { return light == Illuminant::D65 ? cie_d65(lambda_nm) : 1.0; }

// XYZ of the light itself from the 1 nm table entries.
glm::dvec3 light_xyz(Illuminant light) {
  glm::dvec3 xyz(0.0);
  for (double l = kCieLambdaMinNm; l <= kCieLambdaMaxNm; l += 1.0) xyz += cie_cmf(l) * light_power(light, l);
  return xyz;
}

// ... with Y normalised to 1.
glm::dvec3 reference_white(Illuminant light) {
  const glm::dvec3 xyz = light_xyz(light);
  return xyz / xyz.y;
}

}  // namespace

WavelengthSamples wavelength_samples(double spacing_nm, Illuminant light) {
  const double span = kCieLambdaMaxNm - kCieLambdaMinNm;
  if (!(spacing_nm > 0.0 && spacing_nm <= span)) throw Error("wavelength spacing must lie in (0, 470] nm");
  const int intervals = static_cast<int>(std::ceil(span / spacing_nm - 1e-9));
  const double h = span / intervals;
  WavelengthSamples s;
  double y_total = 0.0;
  for (int i = 0; i <= intervals; ++i) {
    const double lambda = kCieLambdaMinNm + i * h;
    const double end_weight = (i == 0 || i == intervals) ? 0.5 : 1.0;
    s.lambda_nm.push_back(lambda);
    s.xyz_weight.push_back(cie_cmf(lambda) * light_power(light, lambda) * (h * end_weight));
    y_total += s.xyz_weight.back().y;
  }
  for (auto& w : s.xyz_weight) w /= y_total;
  return s;
}

glm::dvec3 xyz_density(double lambda_nm, Illuminant light) {
  static const double y_d65 = light_xyz(Illuminant::D65).y, y_e = light_xyz(Illuminant::E).y;
  return cie_cmf(lambda_nm) * light_power(light, lambda_nm) / (light == Illuminant::D65 ? y_d65 : y_e);
}

double observer_spacing(double tolerance, Illuminant light) {
  const glm::dvec3 white = reference_white(light);
  for (int intervals = 1; intervals <= 470; ++intervals) {
    const double spacing = 470.0 / intervals;
    const glm::dvec3 xyz = integrate_xyz(wavelength_samples(spacing, light), [](double) { return 1.0; });
    const glm::dvec3 error = glm::abs(xyz - white);
    if (std::max({error.x, error.y, error.z}) <= tolerance) return spacing;
  }
  return 1.0;
}

double peak_spacing(const SpectralTables& tables, double lambda_min_nm, double tolerance) {
  const double k_max = 2.0 * std::numbers::pi / lambda_min_nm;
  const double s = lambda_min_nm / (std::sqrt(2.0) * k_max * tables.sigma_nm * 2.0);
  return s * std::numbers::pi * std::sqrt(2.0 / std::log(4.0 / tolerance));  // half the tolerance for the aliases
}

WavelengthSamples diffraction_wavelength_samples(const SpectralTables& tables, double tolerance, Illuminant light) {
  return wavelength_samples(
      std::min(observer_spacing(tolerance, light), peak_spacing(tables, kCieLambdaMinNm, tolerance)), light);
}

glm::dvec3 integrate_xyz(const WavelengthSamples& samples, const std::function<double(double)>& f) {
  glm::dvec3 xyz(0.0);
  for (size_t i = 0; i < samples.lambda_nm.size(); ++i) xyz += f(samples.lambda_nm[i]) * samples.xyz_weight[i];
  return xyz;
}

glm::dvec3 integrate_linear_srgb(const WavelengthSamples& samples, const std::function<double(double)>& f) {
  return kernels::f64::spectral_xyz_to_linear_srgb(integrate_xyz(samples, f));
}

}  // namespace facet::diffraction
