// Moment MIP maps (renderer/precompute/moment_mips.cpp): every texel of every level against the
// brute-force mean and variance of the level-0 texels it covers, for odd, non-power-of-two sizes; the
// within-texel variance against midpoint quadrature of the bilinear texture; LEAN slope moments
// against their definition; the lookup at texel centres and with extreme inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "precompute/moment_mips.hpp"

namespace {

using namespace facet::precompute;
using facet::assets::ScalarField;

ScalarField random_field(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.3, 0.2);
  ScalarField f{width, height, std::vector<double>(static_cast<std::size_t>(width) * height)};
  for (double& v : f.values) v = normal(rng);
  return f;
}

// Level l texel (x, y) covers level-0 texels [x 2^l, min((x + 1) 2^l, W)) and likewise in y.
template <typename Visit>
void for_covered(const ScalarField& f, int level, int x, int y, Visit visit) {
  const int span = 1 << level;
  for (int j = y * span; j < std::min((y + 1) * span, f.height); ++j)
    for (int i = x * span; i < std::min((x + 1) * span, f.width); ++i) visit(i, j);
}

// Sizes 13x7 (odd at every level), 1x5 and 16x16: means to 1e-15 (sums of <= 91 numbers of order 1),
// variances E[t^2] - E[t]^2 to 1e-14 (the difference cancels ~1 digit for variance ~0.04 vs mean^2 ~0.1).
TEST(MomentMips, EveryLevelHoldsTheMomentsOfItsCoveredTexels) {
  for (auto [w, h] : {std::pair{13, 7}, std::pair{1, 5}, std::pair{16, 16}}) {
    const ScalarField f = random_field(w, h, 3);
    const MomentMips mips = scalar_moment_mips(f);
    ASSERT_EQ(mips.levels.back().width, 1);
    ASSERT_EQ(mips.levels.back().height, 1);
    for (int l = 0; l < static_cast<int>(mips.levels.size()); ++l)
      for (int y = 0; y < mips.levels[l].height; ++y)
        for (int x = 0; x < mips.levels[l].width; ++x) {
          double n = 0, sum = 0, within = 0;
          for_covered(f, l, x, y, [&](int i, int j) {
            n += 1;
            sum += f.at(i, j);
            within += mips.texel(0, i, j)[kScalarWithinVariance];
          });
          const double mean = sum / n;
          double var = 0;
          for_covered(f, l, x, y, [&](int i, int j) { var += (f.at(i, j) - mean) * (f.at(i, j) - mean); });
          var /= n;
          const double* t = mips.texel(l, x, y);
          EXPECT_NEAR(t[kScalarMean], mean, 1e-15) << w << "x" << h << " level " << l;
          EXPECT_NEAR(t[kScalarSecondMoment] - t[kScalarMean] * t[kScalarMean], var, 1e-14) << l;
          EXPECT_NEAR(t[kScalarWithinVariance], within / n, 1e-15) << l;
        }
  }
}

// The within-texel variance is that of the bilinear texture over the texel's cell: against a 400x400
// midpoint rule on the cell (the rule is exact for the bilinear t on each quarter and errs by
// O(h^2 |t_x t_y|) ~ 1e-7 for t^2; tolerance 1e-6 on variances ~0.01).
TEST(MomentMips, WithinTexelVarianceIsThatOfTheBilinearTextureOverTheCell) {
  const ScalarField f = random_field(5, 4, 11);
  const MomentMips mips = scalar_moment_mips(f);
  auto bilinear = [&](double x, double y) {  // independent of the library's: texel centres at i + 1/2
    const double sx = x - 0.5, sy = y - 0.5;
    const int i = static_cast<int>(std::floor(sx)), j = static_cast<int>(std::floor(sy));
    const double wx = sx - i, wy = sy - j;
    return (1 - wx) * (1 - wy) * f.wrapped(i, j) + wx * (1 - wy) * f.wrapped(i + 1, j) +
           (1 - wx) * wy * f.wrapped(i, j + 1) + wx * wy * f.wrapped(i + 1, j + 1);
  };
  const int n = 400;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      double s1 = 0, s2 = 0;
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
          const double t = bilinear(x + (a + 0.5) / n, y + (b + 0.5) / n);
          s1 += t;
          s2 += t * t;
        }
      s1 /= n * n;
      s2 /= n * n;
      EXPECT_NEAR(mips.texel(0, x, y)[kScalarWithinVariance], s2 - s1 * s1, 1e-6) << x << " " << y;
    }
}

// LEAN channels: level 0 from central differences; the top level holds the field's global moments,
// and the mean slope of a periodic field is 0 (central differences telescope).
TEST(MomentMips, LeanMomentsFollowTheirDefinition) {
  const ScalarField f = random_field(9, 6, 5);
  const double texel = 0.25;
  const MomentMips mips = lean_moment_mips(f, texel);
  double sxsy = 0, h2 = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const double sx = (f.wrapped(x + 1, y) - f.wrapped(x - 1, y)) / (2 * texel);
      const double sy = (f.wrapped(x, y + 1) - f.wrapped(x, y - 1)) / (2 * texel);
      const double* t = mips.texel(0, x, y);
      EXPECT_DOUBLE_EQ(t[kLeanSx], sx);
      EXPECT_DOUBLE_EQ(t[kLeanSy], sy);
      EXPECT_DOUBLE_EQ(t[kLeanSxSy], sx * sy);
      sxsy += sx * sy;
      h2 += f.at(x, y) * f.at(x, y);
    }
  const double* top = mips.texel(static_cast<int>(mips.levels.size()) - 1, 0, 0);
  EXPECT_NEAR(top[kLeanSx], 0.0, 1e-14);
  EXPECT_NEAR(top[kLeanSy], 0.0, 1e-14);
  EXPECT_NEAR(top[kLeanSxSy], sxsy / (f.width * f.height), 1e-13);
  EXPECT_NEAR(top[kLeanH2], h2 / (f.width * f.height), 1e-15);
}

// Flattened offsets: contiguous, level after level, sizes ceil-halved.
TEST(MomentMips, FlattenedLevelsAreContiguous) {
  const MomentMips mips = scalar_moment_mips(random_field(13, 7, 1));
  std::size_t offset = 0;
  int w = 13, h = 7;
  for (const MomentLevel& l : mips.levels) {
    EXPECT_EQ(l.offset, offset);
    EXPECT_EQ(l.width, w);
    EXPECT_EQ(l.height, h);
    offset += static_cast<std::size_t>(l.width) * l.height * mips.channels;
    w = (w + 1) / 2;
    h = (h + 1) / 2;
  }
  EXPECT_EQ(mips.flatten_f32().size(), offset);
  EXPECT_EQ(mips.levels.size(), 5u);  // 13 -> 7 -> 4 -> 2 -> 1
}

// At a texel centre of a power-of-two level the lookup is that texel (mean, sample variance plus
// within-texel variance); between levels it is the linear blend; extreme inputs stay finite.
TEST(MomentMips, LookupInterpolatesAndClamps) {
  const ScalarField f = random_field(16, 8, 9);
  const MomentMips mips = scalar_moment_mips(f);
  auto expected = [&](int level, int x, int y) {
    const double* t = mips.texel(level, x, y);
    return MeanVariance{t[0], t[1] - t[0] * t[0] + t[2]};
  };
  for (int level : {0, 1, 2}) {
    const int span = 1 << level;
    const glm::dvec2 uv((3 + 0.5) * span / 16.0, (1 + 0.5) * span / 8.0);
    const MeanVariance got = lookup_scalar_moments(mips, uv, level), want = expected(level, 3, 1);
    EXPECT_NEAR(got.mean, want.mean, 1e-14);
    EXPECT_NEAR(got.variance, want.variance, 1e-14);
  }
  // The top level (1x1) is the whole field, whatever uv; lod beyond the chain clamps to it.
  const int top = static_cast<int>(mips.levels.size()) - 1;
  const MeanVariance whole = lookup_scalar_moments(mips, {0.37, 0.81}, 100.0), want = expected(top, 0, 0);
  EXPECT_NEAR(whole.mean, want.mean, 1e-15);
  EXPECT_NEAR(whole.variance, want.variance, 1e-15);
  for (double u : {-1e300, -1.5, 0.0, 1.0, 1e300, std::nan("")})
    for (double lod : {-5.0, 0.0, 2.5, 1e9, std::nan("")}) {
      const MeanVariance mv = lookup_scalar_moments(mips, {u, 0.3}, lod);
      EXPECT_TRUE(std::isfinite(mv.mean) && std::isfinite(mv.variance) && mv.variance >= 0.0) << u << " " << lod;
    }
}

// A footprint 8 texels long (x) and 1 wide at level 0: 8 taps on the texel centres of one row, so the
// mixture is exactly the mean and variance of those 8 samples plus their mean within-texel variance.
TEST(MomentMips, AnisotropicTapsCombineAsAMixture) {
  const ScalarField f = random_field(16, 8, 21);
  const MomentMips mips = scalar_moment_mips(f);
  const int row = 5;
  const MeanVariance got =
      lookup_scalar_moments_anisotropic(mips, {4.0 / 16, (row + 0.5) / 8}, {8.0 / 16, 0.0}, {0.0, 1.0 / 8}, 16);
  double mean = 0, within = 0;
  for (int i = 0; i < 8; ++i) {
    mean += f.at(i, row) / 8;
    within += mips.texel(0, i, row)[kScalarWithinVariance] / 8;
  }
  double var = 0;
  for (int i = 0; i < 8; ++i) var += (f.at(i, row) - mean) * (f.at(i, row) - mean) / 8;
  EXPECT_NEAR(got.mean, mean, 1e-14);
  EXPECT_NEAR(got.variance, var + within, 1e-14);
  // A footprint inside one texel is the single trilinear lookup at level 0.
  const MeanVariance one = lookup_scalar_moments_anisotropic(mips, {0.3, 0.6}, {0.01, 0.0}, {0.0, 0.02}, 16);
  const MeanVariance iso = lookup_scalar_moments(mips, {0.3, 0.6}, 0.0);
  EXPECT_DOUBLE_EQ(one.mean, iso.mean);
  EXPECT_DOUBLE_EQ(one.variance, iso.variance);
}

}  // namespace
