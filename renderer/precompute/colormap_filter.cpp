#include "precompute/colormap_filter.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "kernels/shared.hpp"

namespace facet::precompute {

namespace {

// A segment farther than this many sigma from mu contributes exactly 0 (Phi(-40) = 4e-350 underflows
// in double, and in float long before), so the loop visits only the segments within reach.
constexpr double kReachSigmas = 40.0;

// Sum of the two constant tails and the K - 1 segments, in parameter units t = (v - lo)/(hi - lo),
// each control point's knot evaluated once. Steps hold colour k on [x_k, x_{k+1}): c0 = c1.
template <typename K, typename Real, typename Vec3>
Vec3 sum_segments(const Colormap& map, Real mu_t, Real sigma_t) {
  const std::vector<double>& x = map.positions();
  const std::vector<glm::dvec3>& c = map.colours();
  const bool steps = map.interpolation() == Colormap::Interpolation::Steps;
  const std::size_t last = x.size() - 1;
  auto z = [&](std::size_t k) { return K::colormap_standardize(Real(x[k]), mu_t, sigma_t); };
  Vec3 sum = Vec3(c.front()) * K::colormap_knot(z(0)).Phi + Vec3(c[last]) * K::colormap_knot(z(last)).Phi_reflected;
  const double reach = kReachSigmas * static_cast<double>(sigma_t);
  // Segments k in [first, end) have x[k + 1] >= mu - reach and x[k] <= mu + reach.
  const std::size_t first = static_cast<std::size_t>(
      std::lower_bound(x.begin() + 1, x.end(), static_cast<double>(mu_t) - reach) - (x.begin() + 1));
  const std::size_t end = std::min<std::size_t>(
      last,
      static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), static_cast<double>(mu_t) + reach) - x.begin()));
  if (first >= end) return sum;
  Real a = z(first);
  auto knot_a = K::colormap_knot(a);
  for (std::size_t k = first; k < end; ++k) {
    const Real b = z(k + 1);
    const auto knot_b = K::colormap_knot(b);
    sum += K::colormap_segment_from_knots(knot_a, knot_b, a, b, Vec3(c[k]), Vec3(steps ? c[k] : c[k + 1]));
    a = b;
    knot_a = knot_b;
  }
  return sum;
}

// The kernel namespaces as template arguments.
struct F64 {
  using ColormapKnot = kernels::f64::ColormapKnot;
  static double colormap_standardize(double x, double mu, double sigma) {
    return kernels::f64::colormap_standardize(x, mu, sigma);
  }
  static ColormapKnot colormap_knot(double z) { return kernels::f64::colormap_knot(z); }
  static glm::dvec3 colormap_segment_from_knots(ColormapKnot k0, ColormapKnot k1, double a, double b, glm::dvec3 c0,
                                                glm::dvec3 c1) {
    return kernels::f64::colormap_segment_from_knots(k0, k1, a, b, c0, c1);
  }
};

struct F32 {
  using ColormapKnot = kernels::f32::ColormapKnot;
  static float colormap_standardize(float x, float mu, float sigma) {
    return kernels::f32::colormap_standardize(x, mu, sigma);
  }
  static ColormapKnot colormap_knot(float z) { return kernels::f32::colormap_knot(z); }
  static glm::vec3 colormap_segment_from_knots(ColormapKnot k0, ColormapKnot k1, float a, float b, glm::vec3 c0,
                                               glm::vec3 c1) {
    return kernels::f32::colormap_segment_from_knots(k0, k1, a, b, c0, c1);
  }
};

}  // namespace

glm::dvec3 filtered_colormap_exact(const Colormap& map, double mu, double sigma) {
  if (sigma == 0.0) return map.at(mu);  // the Dirac limit, also on a step's jump
  const double width = map.domain().y - map.domain().x;
  return sum_segments<F64, double, glm::dvec3>(map, (mu - map.domain().x) / width, sigma / width);
}

glm::vec3 filtered_colormap_exact_f32(const Colormap& map, float mu, float sigma) {
  if (sigma == 0.0f) return glm::vec3(map.at(mu));
  const float lo = static_cast<float>(map.domain().x);
  const float width = static_cast<float>(map.domain().y - map.domain().x);
  return sum_segments<F32, float, glm::vec3>(map, (mu - lo) / width, sigma / width);
}

}  // namespace facet::precompute
