// Pearson's chi-square goodness-of-fit test, for the samplers' tests.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

#include <boost/math/special_functions/gamma.hpp>

namespace facet::test {

// The probability, were the samples drawn from the expected distribution, of a Pearson statistic at
// least as large as that of `observed` against `expected` (counts per cell). Cells expecting fewer
// than 5 samples are pooled into one, so the chi-square approximation holds.
inline double chi_square_p_value(std::span<const double> observed, std::span<const double> expected) {
  double chi2 = 0.0, pooled_e = 0.0, pooled_o = 0.0;
  int cells = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (expected[k] < 5.0) {
      pooled_e += expected[k];
      pooled_o += observed[k];
      continue;
    }
    chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
    ++cells;
  }
  if (pooled_e > 0.0) {
    chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / std::max(pooled_e, 1.0);
    ++cells;
  }
  return boost::math::gamma_q(0.5 * (cells - 1), 0.5 * chi2);
}

}  // namespace facet::test
