// The exact Gaussian filtering of colour maps (shaders/lib/colormap_filter.glsl and its C++ loop
// renderer/precompute/colormap_filter.cpp) against long-double Gauss–Kronrod quadrature
// (gaussian_quadrature.hpp), into the far tails, for tiny and huge sigma, linear and step maps, and
// float against double. Worst errors are recorded as test properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gaussian_quadrature.hpp"
#include "kernels/shared.hpp"
#include "precompute/colormap_filter.hpp"

namespace {

using facet::Colormap;
using facet::test::LongVec3;
namespace k64 = facet::kernels::f64;
namespace k32 = facet::kernels::f32;

const glm::dvec3 kC0{0.9, 0.2, 0.05}, kC1{0.1, 0.6, 0.8};

std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

double max_rel(glm::dvec3 value, LongVec3 ref) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) worst = std::max(worst, static_cast<double>(std::abs((value[i] - ref[i]) / ref[i])));
  return worst;
}

double max_abs(glm::dvec3 value, LongVec3 ref) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) worst = std::max(worst, static_cast<double>(std::abs(value[i] - ref[i])));
  return worst;
}

// Segment [0.2, 0.7], mu in [-2, 3], sigma in [0.01, 10], wherever the value is a normal double (the
// nearer end within 37 sigma of mu; beyond, both underflow): relative error per component. Bound: G's
// z^2 eps growth (37^2 eps = 3e-13) and, at the wide end, eps/(b - a)^2 (2e-14 at sigma = 10).
TEST(ColormapSegment, MatchesQuadratureOnGrid) {
  double worst = 0;
  for (double mu = -2.0; mu <= 3.0; mu += 0.25)
    for (double sigma = 1e-2; sigma <= 10.0; sigma *= 1.3) {
      const double nearest = mu < 0.2 ? 0.2 - mu : (mu > 0.7 ? mu - 0.7 : 0.0);
      if (nearest > 37.0 * sigma) continue;
      const glm::dvec3 got = k64::colormap_segment_gaussian(0.2, 0.7, kC0, kC1, mu, sigma);
      worst = std::max(
          worst, max_rel(got, facet::test::segment_reference(0.2L, 0.7L, LongVec3(kC0), LongVec3(kC1), mu, sigma)));
    }
  RecordProperty("worst_rel_f64", sci(worst));
  EXPECT_LT(worst, 1e-11);
}

// Segments entirely in one tail, down to where phi underflows (z = 37 in double): the reflection to the
// small side keeps relative accuracy; the bound is G's z^2 eps growth (37^2 * 2.2e-16 = 3e-13) plus
// Phi's own error.
TEST(ColormapSegment, FarTailsKeepRelativeAccuracy) {
  double worst = 0;
  for (double z = 1.0; z <= 37.0; z += 0.5)
    for (double width : {0.05, 1.0, 10.0})
      for (int side : {-1, 1}) {
        // [x0, x1] at distance z sigma from mu = 0 (sigma = 1), on either side.
        const double x0 = side > 0 ? z : -z - width, x1 = x0 + width;
        const glm::dvec3 got = k64::colormap_segment_gaussian(x0, x1, kC0, kC1, 0.0, 1.0);
        worst = std::max(
            worst, max_rel(got, facet::test::segment_reference(x0, x1, LongVec3(kC0), LongVec3(kC1), 0.0L, 1.0L)));
      }
  RecordProperty("worst_rel_f64", sci(worst));
  EXPECT_LT(worst, 1e-12);
}

// sigma -> 0: the segment tends to its colour at mu (inside) or 0 (outside); at sigma = 0 exactly the
// kernel clamps sigma to 1e-30 and must still be finite and exact up to rounding.
TEST(ColormapSegment, TinySigmaIsThePointValue) {
  for (double sigma : {0.0, 1e-300, 1e-30, 1e-12, 1e-9})
    for (double mu : {-1.0, 0.1, 0.2 + 1e-6, 0.35, 0.6999, 0.8}) {
      const glm::dvec3 got = k64::colormap_segment_gaussian(0.2, 0.7, kC0, kC1, mu, sigma);
      const double f = (mu - 0.2) / 0.5;
      const glm::dvec3 want = (mu > 0.2 && mu < 0.7) ? kC0 + f * (kC1 - kC0) : glm::dvec3(0);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "sigma " << sigma << " mu " << mu;
    }
  // On an end point the limit is half the end colour (half the mass on each side).
  const glm::dvec3 edge = k64::colormap_segment_gaussian(0.2, 0.7, kC0, kC1, 0.2, 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(edge[i], 0.5 * kC0[i], 1e-15);
  const glm::vec3 edge32 = k32::colormap_segment_gaussian(0.2f, 0.7f, glm::vec3(kC0), glm::vec3(kC1), 0.2f, 0.0f);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(edge32[i], 0.5 * kC0[i], 1e-7);
}

// sigma >> width: the segment is a thin slice of width h = (x1 - x0)/sigma; the closed form differences
// G over it, so its relative error grows like eps/h^2 and its absolute error like eps/h (the value is
// ~0.4 h). Stated bound: 8 eps sigma/(x1 - x0) absolute (measured 5e-13 at sigma = 1e3, bound 3.5e-12).
TEST(ColormapSegment, HugeSigmaStaysFiniteAndAccurate) {
  for (double sigma : {1e2, 1e3, 1e4, 1e6})
    for (double mu : {-3.0, 0.45, 5.0}) {
      const glm::dvec3 got = k64::colormap_segment_gaussian(0.2, 0.7, kC0, kC1, mu, sigma);
      const LongVec3 ref = facet::test::segment_reference(0.2L, 0.7L, LongVec3(kC0), LongVec3(kC1), mu, sigma);
      EXPECT_LT(max_abs(got, ref), 8 * 2.2e-16 * sigma / 0.5) << sigma << " " << mu;
    }
}

// Where the Gaussian stays inside one linear segment (mass outside < Q(40)), filtering a linear
// function is exact: E[c(v)] = c(mu). Map from -50 to 50, mu in [-1, 1], sigma <= 1.
TEST(ColormapFilter, LinearMapIsReproducedInsideASegment) {
  const Colormap map({-50.0, 50.0}, {kC0, kC1}, Colormap::Interpolation::Linear);
  double worst = 0;
  for (double mu = -1.0; mu <= 1.0; mu += 0.125)
    for (double sigma = 1e-6; sigma <= 1.0; sigma *= 3.0) {
      const glm::dvec3 got = facet::precompute::filtered_colormap_exact(map, mu, sigma);
      const glm::dvec3 want = map.at(mu);
      for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(got[i] - want[i]));
    }
  RecordProperty("worst_abs_f64", sci(worst));
  EXPECT_LT(worst, 1e-14);
}

// The whole loop against the segment-wise quadrature, for a built-in 256-point map (linear and steps)
// and an uneven 4-point map with a domain [2, 6]. Absolute error, colours <= 1.
TEST(ColormapFilter, WholeMapsMatchQuadrature) {
  const Colormap uneven({0.0, 0.1, 0.65, 1.0}, {kC0, kC1, glm::dvec3(0.3, 0.3, 0.0), glm::dvec3(1.0)},
                        Colormap::Interpolation::Linear, {2.0, 6.0});
  const Colormap uneven_steps({0.0, 0.1, 0.65, 1.0}, {kC0, kC1, glm::dvec3(0.3, 0.3, 0.0), glm::dvec3(1.0)},
                              Colormap::Interpolation::Steps, {2.0, 6.0});
  double worst = 0;
  for (const Colormap* map : {&uneven, &uneven_steps})
    for (double mu = 1.0; mu <= 7.0; mu += 0.5)
      for (double sigma : {1e-3, 0.05, 0.4, 3.0, 50.0})
        worst = std::max(worst, max_abs(facet::precompute::filtered_colormap_exact(*map, mu, sigma),
                                        facet::test::colormap_reference(*map, mu, sigma)));
  for (auto interpolation : {Colormap::Interpolation::Linear, Colormap::Interpolation::Steps}) {
    const Colormap viridis = facet::builtin_colormap("viridis", interpolation);
    for (double mu : {-0.3, 0.0, 0.37, 0.9, 1.2})
      for (double sigma : {1e-3, 0.02, 0.3})
        worst = std::max(worst, max_abs(facet::precompute::filtered_colormap_exact(viridis, mu, sigma),
                                        facet::test::colormap_reference(viridis, mu, sigma)));
  }
  RecordProperty("worst_abs_f64", sci(worst));
  EXPECT_LT(worst, 1e-13);
}

// sigma = 0 is the point value, also on a step's jump (where sigma -> 0+ gives the mean of both sides).
TEST(ColormapFilter, ZeroSigmaIsTheColormapItself) {
  for (auto interpolation : {Colormap::Interpolation::Linear, Colormap::Interpolation::Steps}) {
    const Colormap map({0.0, 0.25, 1.0}, {kC0, kC1, glm::dvec3(0.5)}, interpolation);
    for (double mu : {-1.0, 0.0, 0.1, 0.25, 0.6, 1.0, 2.0}) {
      const glm::dvec3 got = facet::precompute::filtered_colormap_exact(map, mu, 0.0);
      EXPECT_EQ(got, map.at(mu)) << mu;
      const float mu32 = static_cast<float>(mu);
      EXPECT_EQ(facet::precompute::filtered_colormap_exact_f32(map, mu32, 0.0f), glm::vec3(map.at(mu32))) << mu;
    }
  }
}

// Huge sigma: every finite part of the map carries mass O(1/sigma), each tail half of the rest.
TEST(ColormapFilter, HugeSigmaTendsToTheMeanOfTheEndColours) {
  const Colormap viridis = facet::builtin_colormap("viridis");
  const glm::dvec3 half = 0.5 * (viridis.colours().front() + viridis.colours().back());
  for (double sigma : {1e4, 1e8, 1e30}) {
    const glm::dvec3 got = facet::precompute::filtered_colormap_exact(viridis, 0.5, sigma);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], half[i], 1.0 / sigma + 4e-16) << sigma;  // O(1/sigma) + rounding
  }
}

// The float twin (the GPU's arithmetic) against the double one on the same (float-representable)
// inputs over mu in [-0.5, 1.5], sigma in [1e-5, 2]: a float Phi is good to ~1e-6 relative, summed over
// the telescoping segment sums — stated tolerance 2e-5 absolute on colours <= 1.
TEST(ColormapFilter, FloatTwinMatchesDouble) {
  double worst = 0;
  for (auto interpolation : {Colormap::Interpolation::Linear, Colormap::Interpolation::Steps}) {
    const Colormap viridis = facet::builtin_colormap("viridis", interpolation);
    for (float mu = -0.5f; mu <= 1.5f; mu += 0.0371f)
      for (float sigma = 1e-5f; sigma <= 2.0f; sigma *= 1.6f) {
        const glm::dvec3 d = facet::precompute::filtered_colormap_exact(viridis, mu, sigma);
        const glm::vec3 f = facet::precompute::filtered_colormap_exact_f32(viridis, mu, sigma);
        for (int i = 0; i < 3; ++i) {
          ASSERT_TRUE(std::isfinite(f[i]));
          worst = std::max(worst, std::abs(static_cast<double>(f[i]) - d[i]));
        }
      }
  }
  RecordProperty("worst_abs_f32", sci(worst));
  EXPECT_LT(worst, 2e-5);
}

// The shader loop visits every segment (no reach cut-off): the segment and tail kernels themselves
// must stay finite and in [0, max colour] for any mu, sigma, in both precisions (|z| is clamped).
TEST(ColormapSegment, ExtremeInputsStayFiniteAndBounded) {
  for (double mu : {-1e38, -1e30, -1.0, 0.2, 0.45, 0.7, 1e30, 1e38})
    for (double sigma : {0.0, 1e-38, 1e-30, 1e-3, 1.0, 1e30, 1e38}) {
      const glm::dvec3 d = k64::colormap_segment_gaussian(0.2, 0.7, kC0, kC1, mu, sigma) +
                           k64::colormap_tail_below_gaussian(0.2, kC0, mu, sigma) +
                           k64::colormap_tail_above_gaussian(0.7, kC1, mu, sigma);
      const float mu32 = static_cast<float>(mu), sigma32 = static_cast<float>(sigma);
      const glm::vec3 f = k32::colormap_segment_gaussian(0.2f, 0.7f, glm::vec3(kC0), glm::vec3(kC1), mu32, sigma32) +
                          k32::colormap_tail_below_gaussian(0.2f, glm::vec3(kC0), mu32, sigma32) +
                          k32::colormap_tail_above_gaussian(0.7f, glm::vec3(kC1), mu32, sigma32);
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(std::isfinite(d[i]) && d[i] >= 0.0 && d[i] <= 0.9 + 1e-12) << mu << " " << sigma;
        EXPECT_TRUE(std::isfinite(f[i]) && f[i] >= 0.0f && f[i] <= 0.9f + 1e-6f) << mu << " " << sigma;
      }
    }
}

// Every input the table or a shader may pass: finite, within the colours' range, never NaN.
TEST(ColormapFilter, ExtremeInputsStayFiniteAndBounded) {
  const Colormap viridis = facet::builtin_colormap("viridis", Colormap::Interpolation::Steps);
  for (double mu : {-1e30, -1e5, -1.0, 0.0, 0.5, 1.0, 1e5, 1e30})
    for (double sigma : {0.0, 1e-300, 1e-20, 1e-3, 1.0, 1e10, 1e300}) {
      const glm::dvec3 d = facet::precompute::filtered_colormap_exact(viridis, mu, sigma);
      const glm::vec3 f = facet::precompute::filtered_colormap_exact_f32(viridis, static_cast<float>(mu),
                                                                         static_cast<float>(std::min(sigma, 1e30)));
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(std::isfinite(d[i]) && d[i] >= 0.0 && d[i] <= 1.0 + 1e-12) << mu << " " << sigma;
        EXPECT_TRUE(std::isfinite(f[i]) && f[i] >= 0.0f && f[i] <= 1.0f + 1e-5f) << mu << " " << sigma;
      }
    }
}

}  // namespace
