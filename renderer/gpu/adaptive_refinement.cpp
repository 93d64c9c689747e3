#include "gpu/adaptive_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>

#include "gpu/render_layout.hpp"

namespace facet::gpu {

namespace {

// Sub-footprints per axis of one stratum (render/texture_sampling.glsl: kFilteredSplit, refined_split).
constexpr int kFirstPassSplit = FACET_RENDER_FILTERED_SPLIT;
int stratum_split(int samples_per_axis) {
  if (samples_per_axis == 1) return kFirstPassSplit;
  return std::max(1, (2 * kFirstPassSplit + samples_per_axis - 1) / samples_per_axis);
}

// An upgrade of pixel `index` to level `to`: its work from the pixel's level, and what it removes per unit of it.
struct Upgrade {
  double gain_per_work;
  std::uint32_t index;
  int to;
  double work;
  // The priority queue pops the largest gain first, then the lowest index.
  bool operator<(const Upgrade& other) const {
    return std::tie(gain_per_work, other.index) < std::tie(other.gain_per_work, index);
  }
};

}  // namespace

std::vector<int> refinement_levels(int max_samples_per_axis) {
  std::vector<int> levels;
  for (int k = 2; k < max_samples_per_axis; k *= 2) levels.push_back(k);
  levels.push_back(max_samples_per_axis);
  return levels;
}

double refinement_cost(int samples_per_axis, bool textured) {
  const double k = samples_per_axis, s = textured ? stratum_split(samples_per_axis) : 0;
  return k * k * (1.0 + s * s);
}

double predicted_squared_error(const PixelEstimate& pixel, int samples_per_axis) {
  // The edge term falls as eq. 3 has it for K x K strata (over K), the texture term with the footprints'
  // width (taps per axis K s against the first pass's 2); an untextured pixel's rest as its edge term.
  const double k = samples_per_axis;
  const double edge = pixel.edge > 0.0f ? std::min(pixel.edge, pixel.estimate) : 0.0f;  // NaN: none
  const double rest = pixel.estimate - edge;
  if (!pixel.textured) return (rest * rest + edge * edge) / (k * k);
  const double taps = kFirstPassSplit / (k * stratum_split(samples_per_axis));
  return rest * rest * taps * taps + edge * edge / (k * k);
}

double default_refinement_work(std::size_t pixels) { return 4.0 * static_cast<double>(pixels); }

std::vector<RefinedPixel> plan_refinement(std::span<const PixelEstimate> pixels, const AdaptiveBudget& budget,
                                          int max_samples_per_axis, double work) {
  const std::vector<int> levels = refinement_levels(max_samples_per_axis);
  const float threshold = static_cast<float>(budget.error.value_or(0.0));
  std::vector<std::uint32_t> candidates;
  for (std::size_t i = 0; i < pixels.size(); ++i)
    if (pixels[i].estimate > threshold) candidates.push_back(static_cast<std::uint32_t>(i));  // NaN fails
  std::vector<int> level(pixels.size(), 1);
  if (budget.error) {
    const double target = *budget.error * *budget.error;
    for (std::uint32_t i : candidates) {
      level[i] = levels.back();
      for (int k : levels)
        if (predicted_squared_error(pixels[i], k) <= target) {
          level[i] = k;
          break;
        }
    }
  } else {
    // The best next level of a pixel at `from`: the most predicted squared error removed per unit of work.
    std::priority_queue<Upgrade> upgrades;
    auto offer = [&](std::uint32_t i, int from) {
      const PixelEstimate& p = pixels[i];
      // The first pass is paid already: a pixel at level 1 has cost the refinement nothing.
      const double now = predicted_squared_error(p, from), cost = from == 1 ? 0.0 : refinement_cost(from, p.textured);
      Upgrade best{0.0, i, from, 0.0};
      for (int k : levels)
        if (k > from) {
          const double work_k = refinement_cost(k, p.textured) - cost;
          const double gain = (now - predicted_squared_error(p, k)) / work_k;
          if (gain > best.gain_per_work) best = {gain, i, k, work_k};
        }
      if (best.to != from) upgrades.push(best);
    };
    for (std::uint32_t i : candidates) offer(i, 1);
    double spent = 0.0;
    while (!upgrades.empty()) {
      const Upgrade u = upgrades.top();
      upgrades.pop();
      if (spent + u.work > work) continue;  // a cheaper upgrade further down may still fit
      spent += u.work;
      level[u.index] = u.to;
      offer(u.index, u.to);
    }
  }
  std::vector<RefinedPixel> plan;
  for (std::uint32_t i : candidates)
    if (level[i] > 1) plan.push_back({i, level[i], pixels[i].textured});
  std::ranges::stable_sort(plan, [&](const RefinedPixel& a, const RefinedPixel& b) {
    return pixels[a.index].estimate > pixels[b.index].estimate;
  });
  return plan;
}

std::size_t pixels_within_work(std::span<const RefinedPixel> plan, double work) {
  std::size_t count = 0;
  for (double spent = 0.0; count < plan.size(); ++count) {
    spent += refinement_cost(plan[count].samples_per_axis, plan[count].textured);
    if (!(spent <= work)) break;
  }
  return count;
}

}  // namespace facet::gpu
