// The visible-height node table (renderer/precompute/visible_height_nodes.cpp) against the nodes' definition:
// node k of MS_HEIGHT_NODES is the z with Phi(z)^(1 + lambda) = (k + 1/2) / MS_HEIGHT_NODES, found here by
// bisection on log Phi from std::erfc, independently of the shaders' quantile. The table, interpolated as the
// GPU does, must stay within 1e-4 of it (standard units) on lambda's whole range, and finite for any lambda.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "kernels/shared.hpp"
#include "precompute/visible_height_nodes.hpp"

namespace {

using facet::precompute::visible_height_node_from_table;
using facet::precompute::visible_height_node_table;

// log Phi(z) without cancellation on either side.
double log_normal_cdf(double z) {
  const double tail = 0.5 * std::erfc(std::abs(z) / std::sqrt(2.0));
  return z < 0.0 ? std::log(tail) : std::log1p(-tail);
}

// The z with (1 + lambda) log Phi(z) = log u, by bisection (log Phi rises with z).
double node_by_bisection(int k, double lambda) {
  const double target = std::log((k + 0.5) / MS_HEIGHT_NODES) / (1.0 + lambda);
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (log_normal_cdf(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(VisibleHeightNodes, TheTableInterpolatesTheNodesOfTheirDefinition) {
  const std::vector<double> table = visible_height_node_table();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> log_lambda(std::log(1e-6), 69.0);
  double worst = 0.0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double lambda = trial < 8 ? (trial == 0 ? 0.0 : std::expm1(trial * 0.5)) : std::exp(log_lambda(rng));
    for (int k = 0; k < MS_HEIGHT_NODES; ++k) {
      const double error = std::abs(visible_height_node_from_table(table, k, lambda) - node_by_bisection(k, lambda));
      worst = std::max(worst, error);
      ASSERT_LT(error, 1e-4) << "node " << k << " at lambda " << lambda;
    }
  }
  std::printf("visible-height node table: worst error %.2e (standard units)\n", worst);
  EXPECT_GT(worst, 1e-7);  // the interpolation is not exact between grid points
}

TEST(VisibleHeightNodes, AnyLambdaReadsAFiniteNode) {
  const std::vector<double> table = visible_height_node_table();
  for (double lambda : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1e300,
                        -0.5, 0.0}) {
    for (int k = 0; k < MS_HEIGHT_NODES; ++k) EXPECT_TRUE(std::isfinite(visible_height_node_from_table(table, k, lambda)));
  }
  // Past the table's end, the last grid point: Lambda saturates at e^69 in float (GM_LOG_LAMBDA_MAX).
  EXPECT_EQ(visible_height_node_from_table(table, 3, 1e300), visible_height_node_from_table(table, 3, std::exp(70.0)));
}

}  // namespace
