// Which pixels `filtered:adaptive` renders again with K x K strata (docs/error_estimate.md, "Adaptive
// refinement"): the first pass's per-pixel error estimate ranks them, the budget cuts the ranking.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/render_method.hpp"

namespace facet::gpu {

// The pixels whose estimate exceeds budget.error (0 without one: a pixel estimated exact is never
// refined), most estimated error first, ties by index; without an error or a time budget, only the
// first ceil(2 n / K^2) of them (two more rays per pixel on average). A NaN estimate is not refined.
std::vector<std::uint32_t> ranked_pixels_to_refine(std::span<const float> estimates, const AdaptiveBudget& budget,
                                                   int samples_per_axis);

// How many more pixels fit in `remaining_ms` of device time at `ms_per_pixel` each, at most `limit`.
std::size_t pixels_within_time(double remaining_ms, double ms_per_pixel, std::size_t limit);

}  // namespace facet::gpu
