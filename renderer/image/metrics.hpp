// Pixel-wise error metrics between a test image and a reference of the same size (docs/image_metrics.md).
//
// All throw facet::Error if the sizes differ, an image is empty or a pixel is not finite.
#pragma once

#include "image/image.hpp"
#include "image/stored_precision.hpp"

namespace facet {

// The ε of relative MSE: keeps dark reference pixels from dominating (the value customary in the
// Monte Carlo rendering and denoising literature).
inline constexpr double kRelativeMseEpsilon = 1e-2;

// PSNR's peak is 1, display white in scene-linear units, so PSNR does not move with the reference's
// brightest firefly; it is 10·log10(1/MSE).
inline constexpr double kPsnrPeak = 1.0;

// sqrt(mean over pixels and channels of (a - b)^2).
double rmse(const Image& test, const Image& reference);

// Mean over pixels and channels of (a - b)^2 / (b^2 + ε), b the reference.
double relative_mse(const Image& test, const Image& reference, double epsilon = kRelativeMseEpsilon);

// 10·log10(peak^2 / MSE) in dB; +inf for identical images.
double psnr(const Image& test, const Image& reference, double peak = kPsnrPeak);

// max over pixels and channels of |a - b|.
double max_abs_error(const Image& test, const Image& reference);

// Per-pixel maps for heat maps: mean over channels of |a - b|, and of (a - b)^2 / (b^2 + ε).
ScalarImage absolute_error_map(const Image& test, const Image& reference);
ScalarImage relative_error_map(const Image& test, const Image& reference, double epsilon = kRelativeMseEpsilon);

// absolute_error_map at the resolution the two images were stored with: each sample's |a - b| less the
// most rounding a and b can carry (rounding_bound), not below 0. The true error an error estimate is
// judged against: a half-float reference rounds an exactly shaded pixel by up to 2^-11 of its value,
// which would otherwise rank it among the erring ones.
ScalarImage resolved_error_map(const Image& test, const Image& reference, const StoredPrecision& test_precision,
                               const StoredPrecision& reference_precision);

// Throws facet::Error unless both are non-empty, of equal size, and finite everywhere.
void check_comparable(const Image& test, const Image& reference);

}  // namespace facet
