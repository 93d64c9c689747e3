#include "gpu/adaptive_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace facet::gpu {

std::vector<std::uint32_t> ranked_pixels_to_refine(std::span<const float> estimates, const AdaptiveBudget& budget,
                                                   int samples_per_axis) {
  const float threshold = static_cast<float>(budget.error.value_or(0.0));
  std::vector<std::uint32_t> ranked;
  for (std::size_t i = 0; i < estimates.size(); ++i)
    if (estimates[i] > threshold) ranked.push_back(static_cast<std::uint32_t>(i));  // NaN fails the test
  std::ranges::stable_sort(ranked, [&](std::uint32_t a, std::uint32_t b) { return estimates[a] > estimates[b]; });
  if (!budget.error && !budget.time_ms) {
    const std::size_t k2 = static_cast<std::size_t>(samples_per_axis) * samples_per_axis;
    ranked.resize(std::min(ranked.size(), (2 * estimates.size() + k2 - 1) / k2));
  }
  return ranked;
}

std::size_t pixels_within_time(double remaining_ms, double ms_per_pixel, std::size_t limit) {
  if (!(remaining_ms > 0.0)) return 0;
  if (!(ms_per_pixel > 0.0)) return limit;
  const double fit = std::floor(remaining_ms / ms_per_pixel);
  return fit >= static_cast<double>(limit) ? limit : static_cast<std::size_t>(fit);
}

}  // namespace facet::gpu
