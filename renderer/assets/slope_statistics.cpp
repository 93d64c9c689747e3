#include "assets/slope_statistics.hpp"

namespace facet::assets {

SampleSlopeStatistics forward_difference_slopes(const ScalarField& field, double texel_size) {
  SampleSlopeStatistics stats;
  for (int y = 0; y < field.height; ++y)
    for (int x = 0; x < field.width; ++x) {
      double h = field.at(x, y);
      double s_x = (field.wrapped(x + 1, y) - h) / texel_size;
      double s_y = (field.wrapped(x, y + 1) - h) / texel_size;
      stats.mean_x += s_x;
      stats.mean_y += s_y;
      stats.var_x += s_x * s_x;
      stats.var_y += s_y * s_y;
      stats.cov_xy += s_x * s_y;
    }
  double n = static_cast<double>(field.values.size());
  stats.mean_x /= n;
  stats.mean_y /= n;
  stats.var_x /= n;
  stats.var_y /= n;
  stats.cov_xy /= n;
  return stats;
}

}  // namespace facet::assets
