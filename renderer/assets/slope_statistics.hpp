// Slope statistics of a periodic grid field measured with forward differences,
// s_x = (h[i+1, j] − h[i, j]) / Δ and s_y = (h[i, j+1] − h[i, j]) / Δ (wrapping at the borders):
// the slopes of the bilinear surface along the cell edges.
#pragma once

#include "assets/scalar_field.hpp"

namespace facet::assets {

struct SampleSlopeStatistics {
  double mean_x = 0.0, mean_y = 0.0;              // 0 for a periodic field, up to rounding
  double var_x = 0.0, var_y = 0.0, cov_xy = 0.0;  // second moments about zero, 1/N
};

SampleSlopeStatistics forward_difference_slopes(const ScalarField& field, double texel_size);

}  // namespace facet::assets
