// The microflake lobe averaged over a pixel (shaders/lib/microflake_pixel_lobe.glsl, eqs. F1-F3 of
// docs/microflake_brdf.md): D over the pixel's parallelogram of half-vector slopes against brute-force
// midpoint quadrature written here, the point lobe for a point pixel, the lobe's energy kept over a block of
// pixels, the radiance over the pixel against the mean of the point radiance over a sphere's pixel, the
// float twin against the double one, extreme inputs finite.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "kernels/shared.hpp"

namespace facet {
namespace {

namespace k64 = kernels::f64;
namespace k32 = kernels::f32;

glm::dvec3 direction_of_slope(glm::dvec2 s) { return glm::normalize(glm::dvec3(-s.x, -s.y, 1.0)); }

// The mean of D(direction of s0 + a step_x + b step_y) over a, b in [-1/2, 1/2], midpoint rule n x n.
double box_average(int ndf, double param, glm::dvec2 s0, glm::dvec2 step_x, glm::dvec2 step_y, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
      sum += k64::ndf_D(ndf, direction_of_slope(s0 + a * step_x + b * step_y), param);
    }
  return sum / (double(n) * n);
}

struct Lobe {
  const char* name;
  int ndf;
  double param;
  double width;      // the lobe's width in slope, to scale the pixels
  double tolerance;  // of the largest pixel mean over the offsets, absolute (measured, with a margin)
};

// Each distribution, narrow and moderate, under pixels from a tenth of the lobe to 30 lobes wide (at most 1.2
// in slope, ~50 degrees of normals), square and sheared, at offsets from the peak inside the pixel to beyond
// it. Held to the measured error with a margin: narrow lobes within 1.4e-2 of the peak (Beckmann and SG 3.8e-3,
// the pixel density's error on a sheared pixel and one h_z for the pixel; GGX 1.3e-2, KK 1.4e-2, their
// mixtures' residual); moderate lobes under pixels as wide as 0.2 to 1 in slope within 0.1 (one h_z for a
// pixel over which h_z^4 varies by up to 2x).
TEST(MicroflakePixelLobe, DensityIsTheMeanOverThePixel) {
  const Lobe lobes[] = {
      {"Beckmann 0.02", NDF_BECKMANN, 0.02, 0.02, 6e-3},
      {"Beckmann 0.2", NDF_BECKMANN, 0.2, 0.2, 0.1},
      {"SG 0.02", NDF_SG, 0.02, 0.02, 6e-3},
      {"SG 0.2", NDF_SG, 0.2, 0.2, 0.09},
      {"GGX 0.02", NDF_GGX, 0.02, 0.02, 2e-2},
      {"GGX 0.2", NDF_GGX, 0.2, 0.2, 0.15},
      {"KK 0.999", NDF_KK, 0.999, 0.045, 2.5e-2},
      {"KK 0.99", NDF_KK, 0.99, 0.14, 0.15},
  };
  for (const Lobe& lobe : lobes)
    for (double size : {0.1, 1.0, 5.0, 30.0})
      for (double shear : {0.0, 0.6}) {
        if (size * lobe.width > 1.2) continue;  // pixels spanning more than ~50 degrees of normals
        const glm::dvec2 step_x = size * lobe.width * glm::dvec2(1.0, 0.0);
        const glm::dvec2 step_y = size * lobe.width * glm::dvec2(shear, 0.8);
        double peak = 0.0, worst = 0.0;
        for (double a : {0.0, 0.3, 0.5, 0.8})
          for (double b : {0.0, 0.45, 1.2}) {
            const glm::dvec2 s0 = a * step_x + b * step_y + glm::dvec2(0.3, -0.2) * lobe.width;
            const double expected = box_average(lobe.ndf, lobe.param, s0, step_x, step_y, 600);
            const double got =
                k64::microflake_D_over_pixel(lobe.ndf, lobe.param, direction_of_slope(s0), glm::dvec4(step_x, step_y));
            peak = std::max(peak, expected);
            worst = std::max(worst, std::abs(got - expected));
          }
        std::printf("%-14s pixel %5.1f lobes, shear %.1f: peak %10.4g, worst error %.2e of the peak\n", lobe.name, size,
                    shear, peak, worst / peak);
        EXPECT_LT(worst, lobe.tolerance * peak) << lobe.name << " " << size << " " << shear;
      }
}

// A point pixel gives the point lobe, exactly.
TEST(MicroflakePixelLobe, PointPixelIsThePointLobe) {
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG})
    for (glm::dvec3 h : {glm::dvec3(0.0, 0.0, 1.0), glm::normalize(glm::dvec3(0.1, -0.3, 0.9))})
      EXPECT_EQ(k64::microflake_D_over_pixel(ndf, 0.05, h, glm::dvec4(0.0)), k64::ndf_D(ndf, h, 0.05));
}

// Over a block of pixels tiling the slopes around a lobe far narrower than one pixel, the pixel means times
// the pixel's area add up to the lobe's projected mass (what a box filter keeps) whatever the sub-pixel
// phase; the centres' point values do not.
TEST(MicroflakePixelLobe, NarrowLobeEnergyIsKeptOverABlockOfPixels) {
  const glm::dvec2 step_x(0.01, 0.002), step_y(-0.003, 0.012);
  const double area = std::abs(step_x.x * step_y.y - step_x.y * step_y.x);
  for (int ndf : {NDF_BECKMANN, NDF_SG, NDF_GGX})
    for (glm::dvec2 phase : {glm::dvec2(0.0), glm::dvec2(0.5, 0.0), glm::dvec2(0.3, 0.8)}) {
      double over_pixels = 0.0, at_centres = 0.0;
      for (int i = -12; i <= 12; ++i)
        for (int j = -12; j <= 12; ++j) {
          const glm::dvec2 s0 = (i + phase.x) * step_x + (j + phase.y) * step_y;
          const glm::dvec3 h = direction_of_slope(s0);
          const double h4 = std::pow(h.z, 4.0);  // the density per unit slope is D h_z^4
          over_pixels += k64::microflake_D_over_pixel(ndf, 0.002, h, glm::dvec4(step_x, step_y)) * h4 * area;
          at_centres += k64::ndf_D(ndf, h, 0.002) * h4 * area;
        }
      std::printf("ndf %d phase (%.1f, %.1f): block sum %.5f over pixels, %.4f at the centres\n", ndf, phase.x, phase.y,
                  over_pixels, at_centres);
      // Beckmann and SG within 5e-5; GGX within 2e-2 (its mixture's residual at a pixel centred on the peak,
      // 1.9e-2; its tails beyond the block, 12 pixels of 0.01 around a lobe of 0.002, hold 1/(1 + 60^2))
      EXPECT_NEAR(over_pixels, 1.0, ndf == NDF_GGX ? 0.025 : 1e-3) << ndf;
      if (phase != glm::dvec2(0.0)) {
        EXPECT_GT(std::abs(at_centres - 1.0), 0.3) << ndf;
      }
    }
}

// The radiance over a pixel of a sphere (microflake_radiance_over_pixel with the steps of
// microflake_half_slope_step, smaller_pixel_step) against the mean of the point radiance over the pixel: the normals
// of a sphere under an orthographic pixel, whose half vector's slopes are then nearly linear, around the highlight of a
// narrow lobe. Measured within 3.4e-3 of the highlight's peak (GGX; the others 3e-4), held to 1e-2.
TEST(MicroflakePixelLobe, RadianceOverASpherePixelIsTheMeanOverItsNormals) {
  const glm::dvec3 v(0.0, 0.0, 1.0), l = glm::normalize(glm::dvec3(0.6, 0.2, 0.8));
  const glm::dvec3 h = glm::normalize(v + l);
  const double pixel = 0.01;  // of the unit sphere's radius
  const auto normal_at = [&](glm::dvec2 x) { return glm::dvec3(x, std::sqrt(std::max(1.0 - glm::dot(x, x), 0.0))); };
  const glm::dvec3 E(1.0), ambient(0.0), albedo(1.0);
  for (int ndf : {NDF_BECKMANN, NDF_SG, NDF_GGX, NDF_KK}) {
    const double param = ndf == NDF_KK ? 0.999 : 0.02;
    double peak = 0.0, worst = 0.0;
    for (double a = -3.0; a <= 3.0; a += 0.5)
      for (double b = -3.0; b <= 3.0; b += 0.75) {
        const glm::dvec2 centre = glm::dvec2(h) + pixel * glm::dvec2(a, b);
        const int m = 300;
        double mean = 0.0;
        for (int i = 0; i < m; ++i)
          for (int j = 0; j < m; ++j) {
            const glm::dvec2 x = centre + pixel * glm::dvec2((i + 0.5) / m - 0.5, (j + 0.5) / m - 0.5);
            mean += k64::microflake_radiance(ndf, param, albedo, normal_at(x), v, l, E, 1.0, ambient).x;
          }
        mean /= double(m) * m;
        const glm::dvec3 n = normal_at(centre);
        const glm::dvec2 half = k64::microflake_frame_slope(n, l + v);
        const auto step = [&](glm::dvec2 offset) {
          return k64::smaller_pixel_step(k64::microflake_half_slope_step(n, l, half, normal_at(centre + offset), v),
                                         k64::microflake_half_slope_step(n, l, half, normal_at(centre - offset), v));
        };
        const glm::dvec4 steps(step(glm::dvec2(pixel, 0.0)), step(glm::dvec2(0.0, pixel)));
        const double got = k64::microflake_radiance_over_pixel(ndf, param, albedo, n, v, l, E, 1.0, ambient, steps).x;
        peak = std::max(peak, mean);
        worst = std::max(worst, std::abs(got - mean));
      }
    std::printf("ndf %d: sphere pixel, peak %.4g, worst error %.2e of the peak\n", ndf, peak, worst / peak);
    EXPECT_LT(worst, 1e-2 * peak) << ndf;
  }
}

// The float twin follows the double one, relative to each case's largest value.
TEST(MicroflakePixelLobe, FloatTwinFollowsDouble) {
  double worst = 0.0;
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG})
    for (double size : {0.1, 3.0, 30.0}) {
      const double param = ndf == NDF_KK ? 0.999 : 0.02, width = 0.03;
      const glm::dvec2 step_x = size * width * glm::dvec2(1.0, 0.1), step_y = size * width * glm::dvec2(0.4, 0.9);
      double peak = 0.0, largest_error = 0.0;
      for (double a = -1.0; a <= 1.0; a += 0.125)
        for (double b = -1.0; b <= 1.0; b += 0.25) {
          const glm::dvec3 h = direction_of_slope(a * step_x + b * step_y);
          const double d64 = k64::microflake_D_over_pixel(ndf, param, h, glm::dvec4(step_x, step_y));
          const double d32 = k32::microflake_D_over_pixel(ndf, static_cast<float>(param), glm::vec3(h),
                                                          glm::vec4(glm::dvec4(step_x, step_y)));
          peak = std::max(peak, d64);
          largest_error = std::max(largest_error, std::abs(d32 - d64));
        }
      worst = std::max(worst, largest_error / peak);
    }
  std::printf("float vs double: %.2e of the peak\n", worst);
  EXPECT_LT(worst, 3e-4);  // measured 1.5e-4
}

// Grazing half vectors, pixels from none to huge, lobes from a near-mirror to near-isotropic flakes, the
// neighbouring normals and views below the horizon: finite and non-negative in both precisions.
TEST(MicroflakePixelLobe, ExtremeInputsStayFinite) {
  int checked = 0;
  const double params[4][3] = {{1e-4, 0.3, 50.0}, {1e-4, 0.3, 50.0}, {1e-6, 0.5, 1.0 - 1e-7}, {1e-4, 0.3, 50.0}};
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG})
    for (double param : params[ndf])
      for (glm::dvec3 h : {glm::dvec3(0.0, 0.0, 1.0), glm::normalize(glm::dvec3(1.0, 0.0, 1e-6))})
        for (glm::dvec4 steps : {glm::dvec4(0.0), glm::dvec4(1e-30, 0.0, 0.0, 1e-30), glm::dvec4(0.01, 0.0, 0.01, 0.0),
                                 glm::dvec4(1e3, 0.0, 0.0, 1e3)}) {
          const double d64 = k64::microflake_D_over_pixel(ndf, param, h, steps);
          const float d32 =
              k32::microflake_D_over_pixel(ndf, static_cast<float>(param), glm::vec3(h), glm::vec4(steps));
          EXPECT_TRUE(std::isfinite(d64) && d64 >= 0.0) << ndf << " " << param << " " << steps.x;
          EXPECT_TRUE(std::isfinite(d32) && d32 >= 0.0f) << ndf << " " << param << " " << steps.x;
          ++checked;
        }
  // a silhouette: the neighbouring normal at 90 degrees, the neighbouring view below the horizon
  const glm::dvec3 n(0.0, 0.0, 1.0), l = glm::normalize(glm::dvec3(0.0, 0.99, 0.01));
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.0, -0.999, 0.001)),
                   below = glm::normalize(v - glm::dvec3(0, 0, 0.01));
  const glm::dvec2 outward =
      k64::microflake_half_slope_step(n, l, k64::microflake_frame_slope(n, l + v), glm::dvec3(0.0, -1.0, 0.0), below);
  const glm::dvec4 steps(k64::smaller_pixel_step(outward, glm::dvec2(1e30)), outward);
  EXPECT_TRUE(std::isfinite(steps.x) && std::isfinite(steps.y) && std::isfinite(steps.z) && std::isfinite(steps.w));
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG}) {
    const glm::dvec3 r = k64::microflake_radiance_over_pixel(ndf, 0.01, glm::dvec3(1.0), n, v, l, glm::dvec3(1.0), 1.0,
                                                             glm::dvec3(0.1), steps);
    EXPECT_TRUE(std::isfinite(r.x) && r.x >= 0.0) << ndf;
    ++checked;
  }
  EXPECT_EQ(checked, 4 * 3 * 2 * 4 + 4);
}

}  // namespace
}  // namespace facet
