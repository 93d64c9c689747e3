// The lobe averaged over a pixel (shaders/lib/microsurface_filter.glsl, eq. P2 of
// docs/microsurface_filtering.md): the slope density over the pixel's parallelogram of half-vector slopes
// against brute-force midpoint quadrature written here, the facet's lobe over the pixel against the mean of
// the point lobe over the pixel's views, the float twin against the double twin, extreme inputs finite.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "kernels/shared.hpp"

namespace facet {
namespace {

namespace k64 = kernels::f64;
namespace k32 = kernels::f32;

// N(s; mean, cov) with cov = (var_x, var_y, c_xy).
double slope_density(glm::dvec2 s, glm::dvec2 mean, glm::dvec3 cov) {
  const glm::dvec2 d = s - mean;
  const double det = cov.x * cov.y - cov.z * cov.z;
  const double q = (cov.y * d.x * d.x - 2.0 * cov.z * d.x * d.y + cov.x * d.y * d.y) / det;
  return std::exp(-0.5 * q) / (2.0 * M_PI * std::sqrt(det));
}

// The mean of N(s0 + a step_x + b step_y; mean, cov) over a, b in [-1/2, 1/2], midpoint rule n x n.
double box_average(glm::dvec2 s0, glm::dvec2 step_x, glm::dvec2 step_y, glm::dvec2 mean, glm::dvec3 cov, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
      sum += slope_density(s0 + a * step_x + b * step_y, mean, cov);
    }
  return sum / (double(n) * n);
}

struct PixelCase {
  const char* name;
  glm::dvec3 cov;
  glm::dvec2 step_x, step_y;
  double tolerance;  // of the largest density over the offsets, absolute
};

// Lobes from far wider to far narrower than the pixel, round and anisotropic with correlation, pixels
// square, long and sheared; the lobe's mean at offsets inside the pixel, on its edges and corners, and
// beyond. Where the edges are orthogonal after whitening the mean is exact: held to the quadrature's
// accuracy (1e-4 of the peak); where they are not (a correlated lobe, a sheared pixel), to the measured
// error of the approximation (the offset along the longer edge taken at its mean across it: 6e-5 and
// 4.3e-3 of the peak) with a margin.
TEST(MicrosurfacePixelLobe, SlopeDensityIsTheMeanOverThePixel) {
  const PixelCase cases[] = {
      {"point pixel", {1e-3, 2e-3, 5e-4}, {1e-7, 0.0}, {0.0, 1e-7}, 1e-6},
      {"wide lobe", {1e-2, 1e-2, 0.0}, {0.01, 0.0}, {0.0, 0.01}, 1e-5},
      {"narrow round lobe, square pixel", {1e-6, 1e-6, 0.0}, {0.02, 0.0}, {0.0, 0.02}, 1e-4},
      {"narrow across, wide along (a streak)", {1e-6, 1e-2, 0.0}, {0.02, 0.0}, {0.0, 0.004}, 1e-4},
      {"lobe as wide as the pixel", {1e-4, 1e-4, 0.0}, {0.02, 0.0}, {0.0, 0.02}, 1e-4},
      {"correlated lobe, rotated square pixel", {2e-5, 1e-5, 1.2e-5}, {0.012, 0.009}, {-0.009, 0.012}, 1e-3},
      {"round lobe, sheared pixel", {2e-5, 2e-5, 0.0}, {0.02, 0.0}, {0.012, 0.016}, 1e-2},
      {"long thin pixel", {1e-5, 1e-5, 0.0}, {0.05, 0.01}, {-0.0005, 0.0025}, 1e-4},
  };
  const glm::dvec2 mean(0.1, -0.05);
  for (const PixelCase& c : cases) {
    double peak = 0.0, worst = 0.0;
    // the centre s0 = mean + offset, the offsets in units of the steps (0.5: the lobe on an edge)
    for (double a : {0.0, 0.25, 0.5, 0.55, 0.8})
      for (double b : {0.0, 0.3, 0.5, 0.7}) {
        const glm::dvec2 s0 = mean + a * c.step_x + b * c.step_y;
        const double expected = box_average(s0, c.step_x, c.step_y, mean, c.cov, 1200);
        const double got = k64::normal_density_over_parallelogram(s0, c.step_x, c.step_y, mean, c.cov, 0.0);
        peak = std::max(peak, expected);
        worst = std::max(worst, std::abs(got - expected));
      }
    std::printf("%-40s peak %10.4g, worst error %.2e of the peak\n", c.name, peak, worst / peak);
    EXPECT_LT(worst, c.tolerance * peak) << c.name;
  }
}

// The lobe over a pixel conserves the lobe's energy: over a block of pixels tiling the slopes around a
// lobe far narrower than one pixel, the means add up to the lobe's integral (1/area of a pixel's
// parallelogram each), whatever the sub-pixel phase; the pixel centres' densities (one point per
// pixel) do not.
TEST(MicrosurfacePixelLobe, NarrowLobeEnergyIsKeptOverABlockOfPixels) {
  const glm::dvec3 cov(4e-6, 2.5e-6, 1e-6);
  const glm::dvec2 step_x(0.01, 0.002), step_y(-0.003, 0.012);
  const double area = std::abs(step_x.x * step_y.y - step_x.y * step_y.x);
  for (glm::dvec2 phase : {glm::dvec2(0.0), glm::dvec2(0.5, 0.0), glm::dvec2(0.5, 0.5), glm::dvec2(0.3, 0.8)}) {
    double over_pixels = 0.0, at_centres = 0.0;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) {
        const glm::dvec2 s0 = (i + phase.x) * step_x + (j + phase.y) * step_y;
        over_pixels += k64::normal_density_over_parallelogram(s0, step_x, step_y, glm::dvec2(0.0), cov, 0.0) * area;
        at_centres += slope_density(s0, glm::dvec2(0.0), cov) * area;
      }
    std::printf("phase (%.1f, %.1f): block sum %.5f over pixels, %.4f at the centres\n", phase.x, phase.y, over_pixels,
                at_centres);
    EXPECT_NEAR(over_pixels, 1.0, 0.01);
    if (phase != glm::dvec2(0.0)) {
      EXPECT_GT(std::abs(at_centres - 1.0), 0.3);  // the point samples miss or over-count the lobe
    }
  }
}

// The facet's lobe over a pixel (beckmann_facet_specular_over_pixel) against the mean of the point lobe
// (beckmann_facet_specular) over the pixel's views, which are camera rays: linear in the film, then
// normalised. The half vector's slope is then only nearly linear over the pixel, and G2 and cos_o vary
// a little: measured within 6e-5 of the lobe's peak here, held to 1e-3. With the neighbouring views
// equal to the centre's it is the point lobe (D of Gaussian slopes is Beckmann's D).
TEST(MicrosurfacePixelLobe, FacetLobeOverThePixelIsTheMeanOverItsViews) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.1, -0.05, 1.0)), tangent(1.0, 0.0, 0.0);
  const glm::dvec3 l = glm::normalize(glm::dvec3(0.0, 0.45, 0.6));
  const glm::dvec2 alpha(0.004, 0.01);
  const glm::dvec3 film_x(0.004, 0.0, 0.0), film_y(0.0, 0.0015, 0.003);  // one pixel step of the ray
  const auto view = [&](glm::dvec3 d, double a, double b) { return glm::normalize(d + a * film_x + b * film_y); };
  // the mirror direction of l about n, and views around it a few pixels apart
  const glm::dvec3 mirror = 2.0 * glm::dot(l, n) * n - l;
  EXPECT_NEAR(k64::beckmann_facet_specular_over_pixel(n, tangent, mirror, l, alpha, mirror, mirror, n, n, n, n) /
                  k64::beckmann_facet_specular(n, tangent, mirror, l, alpha),
              1.0, 1e-9);
  double peak = 0.0, worst = 0.0;
  for (double a = -3.0; a <= 3.0; a += 0.75)
    for (double b = -3.0; b <= 3.0; b += 0.75) {
      const glm::dvec3 d = mirror + a * film_x + b * film_y;  // the pixel centre's ray, reversed
      const int m = 200;
      double mean = 0.0;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
          mean += k64::beckmann_facet_specular(n, tangent, view(d, (i + 0.5) / m - 0.5, (j + 0.5) / m - 0.5), l, alpha);
      mean /= double(m) * m;
      const double got = k64::beckmann_facet_specular_over_pixel(n, tangent, view(d, 0, 0), l, alpha, view(d, 1, 0),
                                                                 view(d, 0, 1), n, n, n, n);
      peak = std::max(peak, mean);
      worst = std::max(worst, std::abs(got - mean));
    }
  std::printf("facet lobe over the pixel: peak %.4g, worst error %.2e of the peak\n", peak, worst / peak);
  EXPECT_LT(worst, 1e-3 * peak);
}

// The facet's lobe over a pixel whose facet normal turns across it (a bilinear patch spanning more than a
// pixel, eq. P3): the view fixed, the normal's slope linear over the pixel, against the mean of the point lobe
// over the pixel's normals, around the mirror configuration of a narrow anisotropic lobe. The half vector's
// slope relative to each normal is linear in the normal's slope only to first order: measured within 4.2e-4
// of the peak here, held to 2e-3. Without the normals' turn (n_x = n_y = n) the lobe is the point lobe's, far off.
TEST(MicrosurfacePixelLobe, FacetLobeOverThePixelIsTheMeanOverItsNormals) {
  const glm::dvec3 tangent(1.0, 0.0, 0.0), l = glm::normalize(glm::dvec3(0.0, 0.45, 0.6));
  const glm::dvec2 alpha(0.004, 0.01);
  const glm::dvec2 turn_x(0.012, 0.002), turn_y(-0.001, 0.009);  // the normal's slope change per pixel step
  const auto normal = [](glm::dvec2 slope) { return glm::normalize(glm::dvec3(-slope.x, -slope.y, 1.0)); };
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.0, -0.45, 0.6));  // the mirror of l about the plane's normal
  double peak = 0.0, worst = 0.0, worst_without = 0.0;
  for (double a = -3.0; a <= 3.0; a += 0.5)
    for (double b = -3.0; b <= 3.0; b += 0.5) {
      const glm::dvec2 centre = a * turn_x + b * turn_y;
      const int m = 200;
      double mean = 0.0;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          const glm::dvec2 slope = centre + ((i + 0.5) / m - 0.5) * turn_x + ((j + 0.5) / m - 0.5) * turn_y;
          mean += k64::beckmann_facet_specular(normal(slope), tangent, v, l, alpha);
        }
      mean /= double(m) * m;
      const glm::dvec3 n = normal(centre);
      const double got = k64::beckmann_facet_specular_over_pixel(n, tangent, v, l, alpha, v, v, normal(centre + turn_x),
                                                                 normal(centre - turn_x), normal(centre + turn_y),
                                                                 normal(centre - turn_y));
      const double without = k64::beckmann_facet_specular_over_pixel(n, tangent, v, l, alpha, v, v, n, n, n, n);
      peak = std::max(peak, mean);
      worst = std::max(worst, std::abs(got - mean));
      worst_without = std::max(worst_without, std::abs(without - mean));
    }
  std::printf("facet lobe over the pixel's normals: peak %.4g, worst error %.2e of the peak (%.2e without)\n", peak,
              worst / peak, worst_without / peak);
  EXPECT_LT(worst, 2e-3 * peak);
  EXPECT_GT(worst_without, 0.5 * peak);
}

// The float twin follows the double one, relative to the largest density of each case.
TEST(MicrosurfacePixelLobe, FloatTwinFollowsDouble) {
  double worst = 0.0;
  for (glm::dvec3 cov : {glm::dvec3(1e-6, 1e-6, 0.0), glm::dvec3(2e-5, 1e-5, 1.2e-5), glm::dvec3(1e-2, 1e-3, 0.0)})
    for (glm::dvec2 step_y : {glm::dvec2(0.0, 0.02), glm::dvec2(0.012, 0.016), glm::dvec2(1e-5, 0.0)}) {
      const glm::dvec2 step_x(0.02, 0.001), mean(0.2, -0.1);
      double peak = 0.0, largest_error = 0.0;
      for (double a = -1.0; a <= 1.0; a += 0.125)
        for (double b = -1.0; b <= 1.0; b += 0.125) {
          const glm::dvec2 s0 = mean + a * step_x + b * step_y;
          const double d64 = k64::normal_density_over_parallelogram(s0, step_x, step_y, mean, cov, 0.0);
          const double d32 = k32::normal_density_over_parallelogram(glm::vec2(s0), glm::vec2(step_x), glm::vec2(step_y),
                                                                    glm::vec2(mean), glm::vec3(cov), 0.0f);
          peak = std::max(peak, d64);
          largest_error = std::max(largest_error, std::abs(d32 - d64));
        }
      worst = std::max(worst, largest_error / peak);
    }
  std::printf("float vs double: %.2e of the peak\n", worst);
  EXPECT_LT(worst, 1e-4);
}

// Degenerate pixels (zero, parallel, huge steps), near-singular and huge covariances, the lobe's mean far
// out in the tails, a neighbouring view below the horizon: finite and non-negative in both precisions.
TEST(MicrosurfacePixelLobe, ExtremeInputsStayFinite) {
  int checked = 0;
  for (glm::dvec3 cov : {glm::dvec3(1e-12, 1e-12, 0.0), glm::dvec3(1e-4, 1e-4, 1e-4), glm::dvec3(1e6, 1e-8, 0.0)})
    for (glm::dvec4 steps : {glm::dvec4(0.0), glm::dvec4(0.01, 0.0, 0.0, 0.0), glm::dvec4(0.01, 0.01, 0.02, 0.02),
                             glm::dvec4(1e3, 0.0, 0.0, 1e3), glm::dvec4(1e-30, 0.0, 0.0, 1e-30)})
      for (glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(0.3, -0.2), glm::dvec2(1e3, 1e3)}) {
        const glm::dvec2 step_x(steps.x, steps.y), step_y(steps.z, steps.w);
        const double d64 = k64::normal_density_over_parallelogram(offset, step_x, step_y, glm::dvec2(0.0), cov, 1e-20);
        const float d32 = k32::normal_density_over_parallelogram(
            glm::vec2(offset), glm::vec2(step_x), glm::vec2(step_y), glm::vec2(0.0f), glm::vec3(cov), 1e-20f);
        EXPECT_TRUE(std::isfinite(d64) && d64 >= 0.0) << cov.x << " " << steps.x << " " << offset.x;
        EXPECT_TRUE(std::isfinite(d32) && d32 >= 0.0f) << cov.x << " " << steps.x << " " << offset.x;
        ++checked;
      }
  // grazing: the neighbouring views below the facet's horizon, and views straight along the light
  const glm::dvec3 n(0.0, 0.0, 1.0), tangent(1.0, 0.0, 0.0), l = glm::normalize(glm::dvec3(0.0, 0.99, 0.01));
  for (glm::dvec3 v : {glm::normalize(glm::dvec3(0.0, -0.999, 0.001)), glm::dvec3(0.0, 0.0, 1.0), l}) {
    const glm::dvec3 below = glm::normalize(v + glm::dvec3(0.0, 0.0, -0.01));
    for (glm::dvec2 alpha : {glm::dvec2(1e-4), glm::dvec2(0.3, 1e3)}) {
      const double f64 = k64::beckmann_facet_specular_over_pixel(n, tangent, v, l, alpha, below, v, below, n, n, below);
      const float f32 = k32::beckmann_facet_specular_over_pixel(
          glm::vec3(n), glm::vec3(tangent), glm::vec3(v), glm::vec3(l), glm::vec2(alpha), glm::vec3(below),
          glm::vec3(v), glm::vec3(below), glm::vec3(n), glm::vec3(n), glm::vec3(below));
      EXPECT_TRUE(std::isfinite(f64) && f64 >= 0.0);
      EXPECT_TRUE(std::isfinite(f32) && f32 >= 0.0f);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3 * 5 * 3 + 3 * 2);
}

}  // namespace
}  // namespace facet
