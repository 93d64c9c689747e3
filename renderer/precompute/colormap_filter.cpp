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

// Sum of the two constant tails and the K - 1 segments, in parameter units t = (v - lo)/(hi - lo).
// Steps hold colour k on [x_k, x_{k+1}): a segment with c0 = c1.
template <typename Real, typename Vec3, typename Kernels>
Vec3 sum_segments(const Colormap& map, Real mu_t, Real sigma_t, Kernels kernels) {
  const std::vector<double>& x = map.positions();
  const std::vector<glm::dvec3>& c = map.colours();
  const bool steps = map.interpolation() == Colormap::Interpolation::Steps;
  const std::size_t last = x.size() - 1;
  Vec3 sum = kernels.tail_below(Real(x.front()), Vec3(c.front()), mu_t, sigma_t) +
             kernels.tail_above(Real(x[last]), Vec3(c[last]), mu_t, sigma_t);
  const double reach = kReachSigmas * static_cast<double>(sigma_t);
  // Segments k in [first, end) have x[k + 1] >= mu - reach and x[k] <= mu + reach.
  const std::size_t first = static_cast<std::size_t>(
      std::lower_bound(x.begin() + 1, x.end(), static_cast<double>(mu_t) - reach) - (x.begin() + 1));
  const std::size_t end = std::min<std::size_t>(
      last, static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), static_cast<double>(mu_t) + reach) - x.begin()));
  for (std::size_t k = first; k < end; ++k)
    sum += kernels.segment(Real(x[k]), Real(x[k + 1]), Vec3(c[k]), Vec3(steps ? c[k] : c[k + 1]), mu_t, sigma_t);
  return sum;
}

struct F64Kernels {
  static glm::dvec3 tail_below(double x, glm::dvec3 c, double mu, double sigma) {
    return kernels::f64::colormap_tail_below_gaussian(x, c, mu, sigma);
  }
  static glm::dvec3 tail_above(double x, glm::dvec3 c, double mu, double sigma) {
    return kernels::f64::colormap_tail_above_gaussian(x, c, mu, sigma);
  }
  static glm::dvec3 segment(double x0, double x1, glm::dvec3 c0, glm::dvec3 c1, double mu, double sigma) {
    return kernels::f64::colormap_segment_gaussian(x0, x1, c0, c1, mu, sigma);
  }
};

struct F32Kernels {
  static glm::vec3 tail_below(float x, glm::vec3 c, float mu, float sigma) {
    return kernels::f32::colormap_tail_below_gaussian(x, c, mu, sigma);
  }
  static glm::vec3 tail_above(float x, glm::vec3 c, float mu, float sigma) {
    return kernels::f32::colormap_tail_above_gaussian(x, c, mu, sigma);
  }
  static glm::vec3 segment(float x0, float x1, glm::vec3 c0, glm::vec3 c1, float mu, float sigma) {
    return kernels::f32::colormap_segment_gaussian(x0, x1, c0, c1, mu, sigma);
  }
};

}  // namespace

glm::dvec3 filtered_colormap_exact(const Colormap& map, double mu, double sigma) {
  if (sigma == 0.0) return map.at(mu);  // the Dirac limit, also on a step's jump
  const double width = map.domain().y - map.domain().x;
  return sum_segments<double, glm::dvec3>(map, (mu - map.domain().x) / width, sigma / width, F64Kernels{});
}

glm::vec3 filtered_colormap_exact_f32(const Colormap& map, float mu, float sigma) {
  if (sigma == 0.0f) return glm::vec3(map.at(mu));
  const float lo = static_cast<float>(map.domain().x);
  const float width = static_cast<float>(map.domain().y - map.domain().x);
  return sum_segments<float, glm::vec3>(map, (mu - lo) / width, sigma / width, F32Kernels{});
}

}  // namespace facet::precompute
