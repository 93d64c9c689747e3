// Periodic (tileable) Gaussian random height fields with a Gaussian autocorrelation function.
//
// The ACF (docs/assets.md, eq. A1), with τ' the lag rotated into the correlation axes:
//   C(τ) = σ_h² exp(−τ'_x²/ℓ_x² − τ'_y²/ℓ_y²) = σ_h² exp(−τᵀAτ),
//   τ'_x = cos θ τ_x + sin θ τ_y,  τ'_y = −sin θ τ_x + cos θ τ_y,
// θ = angle_deg: the ℓ_x axis measured counter-clockwise from the grid's +x axis.
// White noise is filtered in the Fourier domain (FFTW, double) so that the ensemble covariance of
// the grid values is the periodised C exactly; the result is then shifted and scaled so that the
// sample mean is exactly 0 and the sample (population, 1/N) standard deviation exactly σ_h.
#pragma once

#include <cstdint>

#include "assets/scalar_field.hpp"

namespace facet::assets {

struct GaussianHeightfieldParams {
  int width = 256, height = 256;  // grid N×M, texels (= vertices: the field is periodic)
  double texel_size = 1.0;        // Δ, world units
  double sigma_h = 1.0;           // height standard deviation, world units
  double corr_x = 8.0;            // ℓ_x, world units
  double corr_y = 8.0;            // ℓ_y, world units
  double angle_deg = 0.0;         // θ
  std::uint64_t seed = 1;
};

// Slope covariance of the continuous field: Σ_s = −∇∇ᵀC(0) = 2σ_h² A (docs/assets.md, eq. A3).
struct SlopeCovariance {
  double var_x = 0.0, var_y = 0.0, cov_xy = 0.0;
};

// Throws facet::Error (one line) for sizes < 2, non-positive Δ or ℓ, negative σ_h, non-finite
// values, or correlation lengths too long for the period (the ACF must fall below e^−16 σ_h² at
// every other lattice image, so the periodic field is a faithful sample of C).
void validate(const GaussianHeightfieldParams& params);

// C(τ) above, for lag τ = (tau_x, tau_y) in world units (one image, not periodised).
double gaussian_acf(const GaussianHeightfieldParams& params, double tau_x, double tau_y);

SlopeCovariance analytic_slope_covariance(const GaussianHeightfieldParams& params);

ScalarField generate_gaussian_heightfield(const GaussianHeightfieldParams& params);

// "facet:generator", "facet:seed", "facet:sigma_h", "facet:corr_x", "facet:corr_y",
// "facet:angle_deg", "facet:texel_size", the analytic "facet:slope_var_x|y", "facet:slope_cov_xy",
// and the forward-difference slope statistics measured on `field` ("facet:sample_slope_var_x|y",
// "facet:sample_slope_cov_xy").
ExrMetadata heightfield_metadata(const GaussianHeightfieldParams& params, const ScalarField& field);

}  // namespace facet::assets
