// Texel placement of MIP levels of any size (shaders/lib/mip_grid.glsl) and the linearised
// variance of a small tap (shaders/lib/texture_footprint.glsl), the two pieces of the footprint
// lookup that the GPU and the CPU share.
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
      std::vector<double> us{0.0, 1.0, -1.0, 0.5 / count, 1.0 - 0.5 / count, 1.0 / count, std::nextafter(1.0, 0.0),
                             double(NAN), double(INFINITY), -double(INFINITY), 1e300};
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

}  // namespace
