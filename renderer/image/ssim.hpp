// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) on display luma, with their 11x11 Gaussian window,
// σ = 1.5, K1 = 0.01, K2 = 0.03, L = 1 (docs/image_metrics.md).
#pragma once

#include "image/image.hpp"

namespace facet {

inline constexpr int kSsimWindow = 11;

// What the metric looks at: each channel clamped to [0,1] and sRGB-encoded (as the PNG preview shows
// it), then combined into luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' (Rec. 709 weights on encoded values).
ScalarImage display_luma(const Image& image);

// Local SSIM at every position where the whole window fits ("valid" positions): a
// (width-10) x (height-10) map. Throws facet::Error if a side is shorter than 11 or sizes differ.
ScalarImage ssim_map(const ScalarImage& x, const ScalarImage& y);

// Mean of ssim_map over display_luma of both images: 1 for identical images, at most 1.
double ssim(const Image& test, const Image& reference);

}  // namespace facet
