// Texel placement of MIP levels of any size (shaders/lib/mip_grid.glsl), and the linearised variance of
// a small tap and the footprint's principal axes (shaders/lib/texture_footprint.glsl): the pieces of the
// footprint lookup that the GPU and the CPU share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/shared.hpp"

namespace {

namespace k64 = facet::kernels::f64;
namespace k32 = facet::kernels::f32;

// The centre of texel i of level l, in level-0 texels: the middle of the range it covers.
double covered_centre(int i, int span, int size0) { return 0.5 * (i * span + std::min((i + 1) * span, size0)); }

// Bilinear weights between true texel centres reproduce linear functions: blending the centres'
// positions (unwrapped across the period) gives back the lookup position u W, for every level of
// power-of-two, odd and 1-texel sizes, in double (1e-12) and float (8 eps_f W).
TEST(MipGrid, WeightsReproduceThePositionOnEveryLevel) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-2.0, 3.0);
  int cases = 0;
  for (int size0 : {1, 2, 3, 5, 7, 13, 16, 37, 1000}) {
    int count = size0;
    for (int span = 1;; span *= 2) {
      for (int k = 0; k < 200; ++k) {
        const double u = unit(rng);
        const double x0 = (u - std::floor(u)) * size0;
        const k64::MipAxisTaps t = k64::mip_axis_taps(u, size0, span, count);
        ASSERT_GE(t.i0, 0);
        ASSERT_LT(t.i0, count);
        ASSERT_EQ(t.i1, (t.i0 + 1) % count);
        double left = covered_centre(t.i0, span, size0), right = covered_centre(t.i1, span, size0);
        if (right <= left) right += size0;                    // the next period
        if (x0 < left - 1e-9) left -= size0, right -= size0;  // x before the first centre
        const double blended = (1 - t.w1) * left + t.w1 * right;
        ASSERT_NEAR(blended, x0, 1e-12 * size0) << size0 << " span " << span << " u " << u;
        const k32::MipAxisTaps f = k32::mip_axis_taps(static_cast<float>(u), size0, span, count);
        if (f.i0 == t.i0) {
          EXPECT_NEAR(f.w1, t.w1, 8 * 1.2e-7 * size0);
        }
        ++cases;
      }
      if (count == 1) break;
      count = (count + 1) / 2;
    }
  }
  EXPECT_GT(cases, 5000);
}

// On levels whose texels are all whole (the size a multiple of the span: every level of a power-of-two
// size, and the finer levels of others) the shortcut returns the general function's taps and weight bit
// for bit, in float and double, for coordinates across several periods, on texel edges and centres, and
// non-finite ones.
template <typename Taps, typename Real>
void expect_whole_taps_equal(Real u, int size0, int span, int count, Taps general, Taps whole) {
  EXPECT_EQ(whole.i0, general.i0) << size0 << " span " << span << " u " << u;
  EXPECT_EQ(whole.i1, general.i1) << size0 << " span " << span << " u " << u;
  EXPECT_EQ(std::memcmp(&whole.w1, &general.w1, sizeof(Real)), 0)
      << size0 << " span " << span << " count " << count << " u " << u << ": " << whole.w1 << " vs " << general.w1;
}

TEST(MipGrid, WholeTexelLevelsTakeTheShortcutsVeryTaps) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unit(-3.0, 4.0);
  int cases = 0;
  for (int size0 : {1, 2, 4, 16, 256, 4096, 96, 40, 1000}) {
    for (int span = 1; size0 % span == 0; span *= 2) {
      const int count = size0 / span;
      std::vector<double> us{0.0,
                             1.0,
                             -1.0,
                             0.5 / count,
                             1.0 - 0.5 / count,
                             1.0 / count,
                             std::nextafter(1.0, 0.0),
                             double(NAN),
                             double(INFINITY),
                             -double(INFINITY),
                             1e300};
      for (int k = 0; k < 300; ++k) us.push_back(unit(rng));
      for (double u : us) {
        expect_whole_taps_equal(u, size0, span, count, k64::mip_axis_taps(u, size0, span, count),
                                k64::mip_axis_taps_whole(u, count));
        const float f = static_cast<float>(u);
        expect_whole_taps_equal(f, size0, span, count, k32::mip_axis_taps(f, size0, span, count),
                                k32::mip_axis_taps_whole(f, count));
        ++cases;
      }
      if (count == 1) break;
    }
  }
  EXPECT_GT(cases, 10000);
}

TEST(MipGrid, NonFiniteCoordinatesGiveTexelZero) {
  for (double u : {double(NAN), double(INFINITY), -double(INFINITY), 1e300}) {
    const k64::MipAxisTaps t = k64::mip_axis_taps(u, 13, 4, 4);
    EXPECT_GE(t.i0, 0);
    EXPECT_LT(t.i0, 4);
    EXPECT_TRUE(t.w1 >= 0.0 && t.w1 <= 1.0);
  }
}

// t = t0 + g.x + d x_1 x_2 (a bilinear patch) over the tap p + (x w, y w), x, y ~ U(-1/2, 1/2):
// the linearised variance w^2 |g|^2 / 12 misses exactly d^2 w^4 Var(x y) = d^2 w^4 / 144, so
// brute force minus the formula must equal that (midpoint quadrature, 400^2 points: rel 1e-4).
// Taps wider than 2 texels are scaled back to width 2.
TEST(LinearisedTapVariance, MatchesBruteForceUpToTheBilinearTerm) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    const glm::dvec2 g(unit(rng), unit(rng));
    const double d = unit(rng), w = 0.05 + 0.9 * std::abs(unit(rng));
    const glm::dvec2 p(unit(rng), unit(rng));
    auto t = [&](glm::dvec2 q) { return g.x * q.x + g.y * q.y + d * q.x * q.y; };
    const glm::dvec2 gradient = g + d * glm::dvec2(p.y, p.x);  // at the tap's centre
    const int n = 400;
    double sum = 0, sum2 = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double v = t(p + w * glm::dvec2((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5));
        sum += v;
        sum2 += v * v;
      }
    const double brute = sum2 / (n * n) - (sum / (n * n)) * (sum / (n * n));
    const double formula = k64::linearised_tap_variance(gradient, {w, 0.0}, {0.0, w});
    EXPECT_NEAR(brute - formula, d * d * std::pow(w, 4) / 144, 1e-4 * brute + 1e-15) << k;
  }
  // Width 4: the variance of a width-2 tap.
  const glm::dvec2 g(0.3, -0.7);
  EXPECT_DOUBLE_EQ(k64::linearised_tap_variance(g, {4.0, 0.0}, {0.0, 4.0}),
                   k64::linearised_tap_variance(g, {2.0, 0.0}, {0.0, 2.0}));
  EXPECT_EQ(k64::linearised_tap_variance(g, {0.0, 0.0}, {0.0, 0.0}), 0.0);
  EXPECT_EQ(k32::linearised_tap_variance(glm::vec2(1e30f), {0.0f, 0.0f}, {0.0f, 0.0f}), 0.0f);
}

// The covariance of the uniform law on the parallelogram J [-1/2, 1/2]^2 by the midpoint rule on an n x n
// grid of its parameters (exact to O(1/n^2)), in texels.
glm::dmat2 parallelogram_covariance(glm::dvec2 a, glm::dvec2 b, int n) {
  glm::dmat2 c(0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 x = a * ((i + 0.5) / n - 0.5) + b * ((j + 0.5) / n - 0.5);
      c += glm::outerProduct(x, x);
    }
  return c / double(n * n);
}

// The footprint's axes are those of the rectangle with the parallelogram's second moments: for random,
// strongly sheared and axis-aligned parallelograms, (major major^T + minor minor^T) / 12 equals the
// brute-force covariance, the axes are perpendicular, |major| >= |minor| and |major| |minor| = |det J|.
TEST(AnisotropicFootprint, AxesHaveTheParallelogramsSecondMoments) {
  const glm::dvec2 size(64.0, 32.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  std::vector<std::pair<glm::dvec2, glm::dvec2>> cases = {
      {{8.0, 0.0}, {8.0, 1.0}}, {{0.0, 3.0}, {5.0, 0.0}}, {{4.0, 4.0}, {4.1, 3.9}}, {{-2.0, 7.0}, {2.0, -6.5}}};
  for (int k = 0; k < 20; ++k)
    cases.push_back({{coordinate(rng), coordinate(rng)}, {coordinate(rng), coordinate(rng)}});
  for (const auto& [a, b] : cases) {
    const k64::AnisotropicFootprint f = k64::anisotropic_footprint(a / size, b / size, size, 20.0, 1e6);
    const glm::dvec2 major = f.major * size, minor = f.minor * size;
    const glm::dmat2 rectangle = (glm::outerProduct(major, major) + glm::outerProduct(minor, minor)) / 12.0;
    const glm::dmat2 brute = parallelogram_covariance(a, b, 400);
    const double scale = glm::dot(a, a) + glm::dot(b, b);
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(rectangle[c][r], brute[c][r], 1e-5 * scale) << a.x << " " << b.x;
    EXPECT_NEAR(glm::dot(major, minor), 0.0, 1e-12 * scale);
    EXPECT_GE(glm::length(major), glm::length(minor));
    EXPECT_NEAR(glm::length(major) * glm::length(minor), std::abs(a.x * b.y - a.y * b.x), 1e-12 * scale);
    // float agrees with double.
    const k32::AnisotropicFootprint g =
        k32::anisotropic_footprint(glm::vec2(a / size), glm::vec2(b / size), glm::vec2(size), 20.0f, 1e6f);
    EXPECT_NEAR(g.lod, f.lod, 1e-4);
    EXPECT_EQ(g.taps, f.taps);
  }
}

// A thin sliver whose edges are both 8 texels long but which is 0.7 texels thick across: 8 taps at level
// 0 (the derivative vectors as axes would give 2 taps at level 2, blurring it across 8 texels); an
// axis-aligned footprint keeps its own axes; degenerate ones stay finite.
TEST(AnisotropicFootprint, ShearedFootprintsAreFilteredAtTheirWidth) {
  const glm::dvec2 size(256.0, 256.0);
  const k64::AnisotropicFootprint sliver =
      k64::anisotropic_footprint({8.0 / 256, 0.0}, {8.0 / 256, 1.0 / 256}, size, 9.0, 8.0);
  EXPECT_EQ(sliver.taps, 8.0);
  EXPECT_EQ(sliver.lod, 0.0);
  const k64::AnisotropicFootprint aligned =
      k64::anisotropic_footprint({0.0, 2.0 / 256}, {16.0 / 256, 0.0}, size, 9.0, 8.0);
  EXPECT_NEAR(glm::length(aligned.major * size - glm::dvec2(16.0, 0.0)) *
                  glm::length(aligned.major * size + glm::dvec2(16.0, 0.0)),
              0.0, 1e-9);
  EXPECT_NEAR(std::abs(aligned.minor.y * 256), 2.0, 1e-12);
  EXPECT_EQ(aligned.taps, 8.0);
  EXPECT_NEAR(aligned.lod, 0.0, 1e-12);  // width max(2, 16 / 8) = 2
  for (const auto& [a, b] :
       std::vector<std::pair<glm::dvec2, glm::dvec2>>{{{0, 0}, {0, 0}}, {{0.1, 0.2}, {0.1, 0.2}}}) {
    const k64::AnisotropicFootprint f = k64::anisotropic_footprint(a, b, size, 9.0, 8.0);
    EXPECT_TRUE(std::isfinite(f.lod) && std::isfinite(f.taps) && std::isfinite(f.major.x) && std::isfinite(f.major.y) &&
                std::isfinite(f.minor.x) && std::isfinite(f.minor.y));
    EXPECT_GE(f.taps, 1.0);
  }
}

}  // namespace
