// The ray/bilinear-cell kernel (shaders/lib/heightfield_cell.glsl, eq. H3) that the GPU tracer runs in
// float and the reference in double: against a brute-force march of f(t) = z_ray - z_surface in
// double, and float against double on the same inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernels/shared.hpp"

namespace facet {
namespace {

namespace k32 = kernels::f32;
namespace k64 = kernels::f64;

struct CellCase {
  glm::dvec3 o, d;
  glm::dvec4 z;  // z00, z10, z01, z11; the cell is [0, 1]^2
};

// Rays through the unit cell's box from every side, with heights of amplitude `amplitude`.
CellCase random_case(std::mt19937_64& rng, double amplitude) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CellCase c;
  c.z = glm::dvec4(u(rng), u(rng), u(rng), u(rng)) * (2.0 * amplitude) - amplitude;
  const glm::dvec3 target(u(rng), u(rng), (2.0 * u(rng) - 1.0) * amplitude);
  const double polar = std::acos(2.0 * u(rng) - 1.0), azimuth = 2.0 * M_PI * u(rng);
  c.d = glm::dvec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
  c.o = target - 2.0 * c.d;
  return c;
}

// f(t) along the ray over the cell, in double, straight from (H1).
double f_of_t(const CellCase& c, double t) {
  const glm::dvec3 p = c.o + t * c.d;
  return p.z - k64::heightfield_bilinear(c.z, std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0));
}

// The first sign change of f over the part of [0, 4] inside the cell, by marching 20000 steps and
// bisecting; -1 where there is none. Grazing roots (a touch without a sign change) are not sought.
double marched_hit(const CellCase& c) {
  double t_in = 0.0, t_out = 4.0;
  for (int a = 0; a < 2; ++a) {
    if (c.d[a] == 0.0) continue;
    const double t0 = -c.o[a] / c.d[a], t1 = (1.0 - c.o[a]) / c.d[a];
    t_in = std::max(t_in, std::min(t0, t1));
    t_out = std::min(t_out, std::max(t0, t1));
  }
  if (!(t_in < t_out)) return -1.0;
  const int steps = 20000;
  double prev_t = t_in, prev_f = f_of_t(c, t_in);
  for (int s = 1; s <= steps; ++s) {
    const double t = t_in + (t_out - t_in) * s / steps, f = f_of_t(c, t);
    if ((f > 0.0) != (prev_f > 0.0)) {
      double lo = prev_t, hi = t;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((f_of_t(c, mid) > 0.0) == (prev_f > 0.0) ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    prev_t = t;
    prev_f = f;
  }
  return -1.0;
}

double hit64(const CellCase& c) { return k64::heightfield_cell_hit(c.o, c.d, 1.0 / c.d, 0.0, 0.0, c.z, 0.0, 4.0); }
float hit32(const CellCase& c) {
  const glm::vec3 o(c.o), d(c.d);
  return k32::heightfield_cell_hit(o, d, 1.0f / d, 0.0f, 0.0f, glm::vec4(c.z), 0.0f, 4.0f);
}

TEST(HeightFieldCell, DoubleFindsTheMarchedCrossing) {
  std::mt19937_64 rng(7);
  int hits = 0;
  for (int n = 0; n < 3000; ++n) {
    const CellCase c = random_case(rng, n % 2 ? 0.3 : 3.0);
    const double marched = marched_hit(c), exact = hit64(c);
    if (marched < 0.0) {
      // No sign change: a hit may still exist where the ray dips under and out again between two
      // march points, but then f must vanish there.
      if (exact > 0.0) {
        EXPECT_NEAR(f_of_t(c, exact), 0.0, 1e-9) << n;
      }
      continue;
    }
    ++hits;
    ASSERT_GT(exact, 0.0) << n;
    // The march finds a sign change; the kernel can only be earlier if it found a dip root.
    EXPECT_LE(exact, marched + 1e-9) << n;
    EXPECT_NEAR(f_of_t(c, exact), 0.0, 1e-9) << n;
  }
  EXPECT_GT(hits, 1000);
}

TEST(HeightFieldCell, FloatAgreesWithDouble) {
  std::mt19937_64 rng(11);
  int compared = 0;
  for (int n = 0; n < 20000; ++n) {
    const CellCase c = random_case(rng, 1.0);
    const double exact = hit64(c);
    const float single = hit32(c);
    // Transversal crossings only: where |f'| at the root is tiny the root moves by rounding/|f'|.
    if (exact > 0.0) {
      const double h = 1e-6, slope = (f_of_t(c, exact + h) - f_of_t(c, exact - h)) / (2.0 * h);
      if (std::abs(slope) < 0.05) continue;
      ++compared;
      ASSERT_GT(single, 0.0f) << n;
      EXPECT_NEAR(single, exact, 2e-5 * (1.0 + 1.0 / std::abs(slope))) << n;
    } else {
      EXPECT_LT(single, 0.0f) << n;
    }
  }
  EXPECT_GT(compared, 5000);
}

// Vertical and axis-parallel rays (d with zero components) and a ray starting on the surface.
TEST(HeightFieldCell, DegenerateDirections) {
  const glm::dvec4 z(0.1, 0.2, 0.3, 0.4);
  // Straight down at (0.5, 0.5): hits z = 0.25 from o.z = 1 at t = 0.75.
  EXPECT_NEAR(
      k64::heightfield_cell_hit({0.5, 0.5, 1.0}, {0.0, 0.0, -1.0}, {INFINITY, INFINITY, -1.0}, 0.0, 0.0, z, 0.0, 4.0),
      0.75, 1e-15);
  // Outside the cell's x range, vertical: no hit.
  EXPECT_LT(
      k64::heightfield_cell_hit({1.5, 0.5, 1.0}, {0.0, 0.0, -1.0}, {INFINITY, INFINITY, -1.0}, 0.0, 0.0, z, 0.0, 4.0),
      0.0);
  // Along x at constant y = 0 and height 0.15: crosses z = 0.1 + 0.1 u at u = 0.5.
  EXPECT_NEAR(
      k64::heightfield_cell_hit({-1.0, 0.0, 0.15}, {1.0, 0.0, 0.0}, {1.0, INFINITY, INFINITY}, 0.0, 0.0, z, 0.0, 4.0),
      1.5, 1e-15);
  // Starting on the surface and leaving it upwards: no hit at t = 0.
  EXPECT_LT(
      k64::heightfield_cell_hit({0.5, 0.5, 0.25}, {0.0, 0.0, 1.0}, {INFINITY, INFINITY, 1.0}, 0.0, 0.0, z, 0.0, 4.0),
      0.0);
}

}  // namespace
}  // namespace facet
