// Which pixels `filtered:adaptive` renders again, and with how many strata each (docs/error_estimate.md,
// "Adaptive refinement"): the first pass's per-pixel error estimate, split into its texture and edge terms,
// predicts what each number of strata leaves (eq. 7); the budget buys the refinements that remove the most
// predicted squared error per unit of work.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/render_method.hpp"

namespace facet::gpu {

// What the first pass says of a pixel: its whole estimate, the edge term in it (eq. 3), and whether a
// colour-mapped texture's footprints made the rest (the texture term; else the rest is eq. 3's contrast
// term, which strata resolve as they resolve edges).
struct PixelEstimate {
  float estimate;
  float edge;
  bool textured;
};

// A pixel of the second pass and its strata per axis.
struct RefinedPixel {
  std::uint32_t index;
  int samples_per_axis;
  bool textured;
  bool operator==(const RefinedPixel&) const = default;
};

// The strata per axis a pixel may get under filtered:adaptive:K: the powers of two from 2 below K, and K.
std::vector<int> refinement_levels(int max_samples_per_axis);

// The work of a pixel of K x K strata (K = 1: the first pass), in units of a ray or a row of taps: K^2 rays,
// and on a textured pixel K^2 s^2 rows of taps, s the sub-footprints per axis of each stratum
// (render/texture_sampling.glsl: kFilteredSplit = 2 in the first pass, max(1, ceil(4 / K)) when refined).
double refinement_cost(int samples_per_axis, bool textured);

// Eq. 7: the squared error left in a pixel of K x K strata.
double predicted_squared_error(const PixelEstimate& pixel, int samples_per_axis);

// The pixels to refine and their K, most estimated error first (ties by index); a pixel estimated 0 or
// NaN is never refined.
// - budget.error E: every pixel whose estimate exceeds E, at the fewest strata that eq. 7 puts at or below
//   E (else the most);
// - otherwise `work` (refinement_cost units; default_refinement_work without a budget) buys, greedily, the
//   refinements with the most predicted squared error removed per unit.
std::vector<RefinedPixel> plan_refinement(std::span<const PixelEstimate> pixels, const AdaptiveBudget& budget,
                                          int max_samples_per_axis, double work);

// The default budget: two refined strata of a ray and a row of taps per pixel, 4 n units (what the first
// ceil(2 n / 16) textured pixels cost at K = 4).
double default_refinement_work(std::size_t pixels);

// How many of the plan's leading pixels fit in `work` (refinement_cost units).
std::size_t pixels_within_work(std::span<const RefinedPixel> plan, double work);

}  // namespace facet::gpu
