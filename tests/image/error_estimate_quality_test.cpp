// Spearman's rank correlation against a brute-force one written here (ranks by counting, ties by
// their mean rank, then Pearson's formula), its closed-form values, and the calibration table's bins.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "image/error_estimate_quality.hpp"

namespace facet {
namespace error_estimate_quality_test {

// Rank of v[i]: 1 + the values below it + half the other values equal to it.
std::vector<double> brute_ranks(const std::vector<float>& v) {
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    double below = 0, equal = 0;
    for (std::size_t j = 0; j < v.size(); ++j) {
      if (v[j] < v[i]) ++below;
      if (v[j] == v[i] && j != i) ++equal;
    }
    r[i] = 1 + below + equal / 2;
  }
  return r;
}

double brute_spearman(const std::vector<float>& a, const std::vector<float>& b) {
  const std::vector<double> ra = brute_ranks(a), rb = brute_ranks(b);
  const double n = static_cast<double>(a.size());
  double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sa += ra[i];
    sb += rb[i];
    sab += ra[i] * rb[i];
    saa += ra[i] * ra[i];
    sbb += rb[i] * rb[i];
  }
  return (sab - sa * sb / n) / std::sqrt((saa - sa * sa / n) * (sbb - sb * sb / n));
}

TEST(ErrorEstimateQuality, SpearmanIsPearsonOfTheRanksWithTies) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> level(0, 5);  // few levels: many ties
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<float> a(50), b(50);
    for (std::size_t i = 0; i < a.size(); ++i) {
      a[i] = static_cast<float>(level(rng));
      b[i] = a[i] + static_cast<float>(level(rng));
    }
    EXPECT_NEAR(spearman_correlation(a, b), brute_spearman(a, b), 1e-12);
  }
}

TEST(ErrorEstimateQuality, SpearmanOfMonotoneMapsIsOneOrMinusOne) {
  const std::vector<float> x = {0.1f, 3.0f, 2.0f, 7.5f, 4.0f};
  std::vector<float> cubed, negated;
  for (float v : x) {
    cubed.push_back(v * v * v);
    negated.push_back(-std::exp(v));
  }
  EXPECT_DOUBLE_EQ(spearman_correlation(x, cubed), 1.0);
  EXPECT_DOUBLE_EQ(spearman_correlation(x, negated), -1.0);
  EXPECT_EQ(spearman_correlation(x, std::vector<float>(5, 2.0f)), 0.0);  // a constant sample
}

TEST(ErrorEstimateQuality, CalibrationBinsTheTruthByRisingEstimate) {
  const std::vector<float> estimate = {4, 1, 3, 2}, truth = {40, 10, 30, 20};
  const ErrorEstimateQuality q = judge_error_estimate(estimate, truth, 2);
  ASSERT_EQ(q.calibration.size(), 2u);
  EXPECT_DOUBLE_EQ(q.calibration[0].estimate, 1.5);
  EXPECT_DOUBLE_EQ(q.calibration[0].truth, 15.0);
  EXPECT_DOUBLE_EQ(q.calibration[1].estimate, 3.5);
  EXPECT_DOUBLE_EQ(q.calibration[1].truth, 35.0);
  EXPECT_DOUBLE_EQ(q.mean_ratio, 0.1);
  EXPECT_DOUBLE_EQ(q.spearman, 1.0);
}

}  // namespace error_estimate_quality_test
}  // namespace facet
