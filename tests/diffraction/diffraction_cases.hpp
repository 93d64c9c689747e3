// Helpers shared by the diffraction tests: gratings from JSON text, directions, error bounds.
#pragma once

#include <cmath>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "diffraction/diffraction_eval.hpp"
#include "diffraction/spectral_tables.hpp"
#include "scene/grating/grating.hpp"

namespace facet::test {

constexpr double kPi = 3.14159265358979323846;

inline diffraction::Grating grating(const std::string& json) {
  return diffraction::grating_from_json(nlohmann::json::parse(json), "test");
}

// The unit vector with horizontal part (x, y), z >= 0.
inline glm::dvec3 direction(double x, double y) { return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))}; }

// |S| = sqrt(P2 / (4 pi sigma^2)): the windowed transform in units of the patch area (|S| <= W).
inline double field_magnitude(double P2, double sigma_nm) { return std::sqrt(P2 / (4.0 * kPi * sigma_nm * sigma_nm)); }

// W: the largest sum of window weights over the bins near any frequency, so an error of e per
// coefficient moves |S| by at most e W. Bins lie at least (j - 1/2) bin widths from the frequency.
inline double window_weight_bound(const diffraction::SpectralTables& t) {
  const double c = 2.0 * kPi * t.sigma_nm / t.period_nm;
  double one_axis = 1.0;
  for (int j = 1; j <= 64; ++j) one_axis += 2.0 * std::exp(-0.5 * c * c * (j - 0.5) * (j - 0.5));
  return one_axis * one_axis;
}

}  // namespace facet::test
