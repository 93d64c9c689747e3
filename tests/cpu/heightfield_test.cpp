// Ray–height-field intersection (renderer/cpu/heightfield.hpp) against brute-force marching,
// analytic planes, finite differences and its own occlusion query.
#include "cpu/heightfield.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "common/error.hpp"
#include "heightfield_reference.hpp"

namespace facet {
namespace heightfield_test {

using test::ReferenceHeightField;

constexpr double kInf = std::numeric_limits<double>::infinity();

HeightFieldGrid random_grid(int width, int height, double texel_size, double amplitude, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  HeightFieldGrid grid{width, height, std::vector<double>(static_cast<std::size_t>(width) * height), texel_size,
                       amplitude};
  for (double& h : grid.heights) h = uniform(rng);
  return grid;
}

// A rotated, translated frame (orthonormal to rounding).
HeightFieldPlacement tilted_placement(glm::dvec2 size) {
  glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
  glm::dvec3 t = glm::normalize(glm::cross(glm::dvec3(0.1, 1.0, 0.2), n));
  glm::dvec3 b = glm::cross(n, t);
  return {{0.7, -1.3, 2.1}, t, b, n, size};
}

glm::dvec3 world(const HeightFieldPlacement& p, glm::dvec3 local) {
  return p.origin + local.x * p.tangent + local.y * p.bitangent + local.z * p.normal;
}
glm::dvec3 world_direction(const HeightFieldPlacement& p, glm::dvec3 local) {
  return local.x * p.tangent + local.y * p.bitangent + local.z * p.normal;
}

struct LocalRay {
  glm::dvec3 o, d;
};

// Rays over a patch with heights in [−amplitude, amplitude]: from above, from below, and from
// inside the height band, at polar angles up to `max_polar_deg` from the normal (either way).
std::vector<LocalRay> random_rays(glm::dvec2 size, double amplitude, double max_polar_deg, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<LocalRay> rays;
  for (int k = 0; k < count; ++k) {
    double polar = max_polar_deg * std::numbers::pi / 180.0 * std::sqrt(uniform(rng));
    double azimuth = 2.0 * std::numbers::pi * uniform(rng);
    glm::dvec3 d{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), -std::cos(polar)};
    glm::dvec3 target{size.x * (-0.1 + 1.2 * uniform(rng)), size.y * (-0.1 + 1.2 * uniform(rng)),
                      amplitude * (2.0 * uniform(rng) - 1.0)};
    int kind = k % 3;  // 0: from above, 1: from below (upwards), 2: starting inside the band
    if (kind == 1) d.z = -d.z;
    double back = kind == 2 ? 0.3 * amplitude : 3.0 * amplitude;
    rays.push_back({target - d * (back / std::max(std::abs(d.z), 1e-3)), d});
  }
  return rays;
}

TEST(HeightField, NearestHitMatchesBruteForceMarching) {
  // 13 x 7 texels (not powers of two), tiled 3.5 x 4.2 times with partial tiles at the far edges.
  HeightFieldGrid grid = random_grid(13, 7, 0.1, 0.08, 1);
  HeightFieldPlacement placement = tilted_placement({13 * 0.1 * 3.5, 7 * 0.1 * 4.2});
  HeightField field(grid, placement);
  ReferenceHeightField reference{grid, placement};
  int hits = 0, compared = 0;
  double worst = 0.0;
  for (const LocalRay& ray : random_rays(placement.size, 0.08, 80.0, 3000, 2)) {
    glm::dvec3 o = world(placement, ray.o), d = world_direction(placement, ray.d);
    auto hit = field.intersect(o, d);
    auto expected = reference.march(o, d, kInf);
    ASSERT_EQ(hit.has_value(), expected.has_value())
        << "ray " << compared << " t_ref " << expected.value_or(-1) << " t " << (hit ? hit->t : -1.0);
    ++compared;
    if (!hit) continue;
    ++hits;
    double error = std::abs(hit->t - *expected) / *expected;
    worst = std::max(worst, error);
    // Tolerance: the march bisects to adjacent doubles of f's sign change; f has rounding error
    // ~1e-16 · max|z| and slope dz/dt ≥ ~0.1 here, so t agrees to ~1e-14 relative; 1e-9 is the
    // spec's bound.
    EXPECT_LT(error, 1e-9) << "ray " << compared;
  }
  EXPECT_GT(hits, 1500);  // most rays hit: the comparison is not vacuous
  std::printf("worst relative t error over %d hits: %.3g\n", hits, worst);
}

TEST(HeightField, GrazingRaysMatchBruteForceMarching) {
  // 89.99° from the normal: the ray climbs 1.7e-4 per unit length and crosses many cells.
  HeightFieldGrid grid = random_grid(16, 16, 0.1, 0.05, 3);
  HeightFieldPlacement placement = tilted_placement({6.4, 6.4});
  HeightField field(grid, placement);
  ReferenceHeightField reference{grid, placement};
  double polar = 89.99 * std::numbers::pi / 180.0;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int hits = 0;
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    double azimuth = 2.0 * std::numbers::pi * uniform(rng);
    glm::dvec3 d{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                 (k % 2 ? 1.0 : -1.0) * std::cos(polar)};
    glm::dvec3 o{3.2 - 3.0 * d.x, 3.2 - 3.0 * d.y, 0.05 * (2.0 * uniform(rng) - 1.0)};
    glm::dvec3 ow = world(placement, o), dw = world_direction(placement, d);
    auto hit = field.intersect(ow, dw);
    auto expected = reference.march(ow, dw, kInf);
    ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << k;
    if (!hit) continue;
    ++hits;
    worst = std::max(worst, std::abs(hit->t - *expected) / *expected);
  }
  // Tolerance: f'(t) can be ~1e-4 at grazing incidence, so rounding of f (~1e-17) moves the root
  // by ~1e-13 in t; 1e-9 relative leaves ample room.
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(hits, 100);
  std::printf("grazing: worst relative t error over %d hits: %.3g\n", hits, worst);
}

TEST(HeightField, DegenerateGeometryMatchesBruteForceMarching) {
  // Plateaus (integer heights: flat cells, level edges, saddles with e = 0), an axis-aligned frame,
  // and rays along the axes, the diagonals and the vertical, aimed at cell edges: the cases where
  // the quadratic degenerates (A = 0, B = 0) or the ray runs along cell faces.
  HeightFieldGrid grid = random_grid(6, 9, 0.1, 1.0, 14);
  for (double& h : grid.heights) h = std::round(1.5 * h);
  HeightFieldPlacement placement{{0.3, 0.2, -0.1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1.5, 2.0}};
  HeightField field(grid, placement);
  ReferenceHeightField reference{grid, placement};
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int hits = 0;
  double worst = 0.0;
  for (int k = 0; k < 3000; ++k) {
    glm::dvec3 d{std::round(4.0 * uniform(rng) - 2.0) / 2.0, std::round(4.0 * uniform(rng) - 2.0) / 2.0,
                 (k % 2 ? 1.0 : -1.0) * (0.25 + uniform(rng))};
    if (k % 5 == 0) d = {0.0, 0.0, k % 2 ? 1.0 : -1.0};
    glm::dvec3 target{0.1 * std::round(15.0 * uniform(rng)), 0.1 * std::round(20.0 * uniform(rng)) + (k % 3) * 0.05,
                      2.0 * uniform(rng) - 1.0};
    glm::dvec3 o = placement.origin + target - 4.0 * d / std::abs(d.z);
    auto hit = field.intersect(o, d);
    auto expected = reference.march(o, d, kInf);
    ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << k;
    if (!hit) continue;
    ++hits;
    worst = std::max(worst, std::abs(hit->t - *expected) / *expected);
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(hits, 1000);
  std::printf("degenerate: worst relative t error over %d hits: %.3g\n", hits, worst);
}

TEST(HeightField, HitAttributesAreThoseOfTheBilinearSurface) {
  HeightFieldGrid grid = random_grid(9, 11, 0.2, 0.1, 5);
  HeightFieldPlacement placement = tilted_placement({3.0, 3.0});
  HeightField field(grid, placement);
  ReferenceHeightField reference{grid, placement};
  int checked = 0;
  for (const LocalRay& ray : random_rays(placement.size, 0.1, 70.0, 500, 6)) {
    glm::dvec3 o = world(placement, ray.o), d = world_direction(placement, ray.d);
    auto hit = field.intersect(o, d);
    if (!hit) continue;
    glm::dvec3 p = reference.local(hit->position);
    // The point is on the ray and on the surface (rounding of coordinates ~1e-16 · 5).
    EXPECT_LT(glm::length(hit->position - (o + hit->t * d)), 1e-12);
    EXPECT_NEAR(p.z, reference.height(p.x, p.y), 1e-13);
    EXPECT_NEAR(hit->height, p.z, 1e-13);
    EXPECT_NEAR(hit->uv.x, p.x / placement.size.x, 1e-12);
    EXPECT_NEAR(hit->uv.y, p.y / placement.size.y, 1e-12);
    double fx = std::fmod(p.x, 9 * 0.2) / (9 * 0.2), fy = std::fmod(p.y, 11 * 0.2) / (11 * 0.2);
    EXPECT_NEAR(hit->field_uv.x, fx, 1e-12);
    EXPECT_NEAR(hit->field_uv.y, fy, 1e-12);
    // Slope against central differences of the reference surface, away from cell edges where the
    // bilinear slope jumps. Step 1e-6: truncation 0 (the surface is quadratic along each axis,
    // central differences are exact for it), rounding ~1e-16 · 0.1 / 1e-6 = 1e-11.
    double u = p.x / 0.2 - std::floor(p.x / 0.2), v = p.y / 0.2 - std::floor(p.y / 0.2);
    if (std::min({u, v, 1.0 - u, 1.0 - v}) < 1e-4) continue;
    double h = 1e-6;
    double sx = (reference.height(p.x + h, p.y) - reference.height(p.x - h, p.y)) / (2 * h);
    double sy = (reference.height(p.x, p.y + h) - reference.height(p.x, p.y - h)) / (2 * h);
    EXPECT_NEAR(hit->slope.x, sx, 1e-8);
    EXPECT_NEAR(hit->slope.y, sy, 1e-8);
    // The normal is unit, on the upper side, and orthogonal to both surface tangents T + s_x N and B + s_y N.
    EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-14);
    EXPECT_GT(glm::dot(hit->normal, placement.normal), 0.0);
    EXPECT_NEAR(glm::dot(hit->normal, placement.tangent + sx * placement.normal), 0.0, 1e-8);
    EXPECT_NEAR(glm::dot(hit->normal, placement.bitangent + sy * placement.normal), 0.0, 1e-8);
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(HeightField, FlatFieldIsThePlane) {
  // A constant field at height c is the plane z = c: t = (c − o_z)/d_z exactly up to rounding,
  // normal N, for rays through vertices, along cell edges, straight down and grazing.
  HeightFieldGrid grid{8, 8, std::vector<double>(64, 0.25), 0.5, 2.0};
  HeightFieldPlacement placement = tilted_placement({10.0, 6.0});
  HeightField field(grid, placement);
  struct Case {
    glm::dvec3 o, d;
  };
  double graze = std::cos(89.99 * std::numbers::pi / 180.0);
  std::vector<Case> cases = {
      {{2.0, 3.0, 4.0}, {0.0, 0.0, -1.0}},                  // straight down through a vertex
      {{2.25, 3.0, 4.0}, {0.0, 0.0, -1.0}},                 // straight down onto a cell edge
      {{1.0, 1.0, 1.5}, {1.0, 1.0, -1.0}},                  // diagonally through vertices
      {{0.1, 5.5, 0.55}, {1.0, 0.0, -0.01}},                // along a row of cell edges, shallow
      {{0.0, 0.3, 0.5 + graze * 5.0}, {1.0, 0.0, -graze}},  // 89.99°, lands at x = 5
      {{9.9, 0.1, -1.0}, {-0.3, 0.2, 1.0}},                 // from below
      {{-3.0, 2.0, 1.0}, {1.0, 0.0, -0.1}},                 // from outside the footprint
  };
  for (const Case& c : cases) {
    auto hit = field.intersect(world(placement, c.o), world_direction(placement, c.d));
    ASSERT_TRUE(hit.has_value()) << c.o.x << " " << c.o.y;
    double t = (0.5 - c.o.z) / c.d.z;
    EXPECT_NEAR(hit->t, t, 1e-12 * t);
    EXPECT_NEAR(hit->height, 0.5, 1e-15);
    EXPECT_LT(glm::length(hit->normal - placement.normal), 1e-15);
  }
  // Parallel to the plane: above, below and exactly in it (a degenerate touch counted as a miss).
  // Axis-aligned frame so that "exactly" survives the world-to-patch transform.
  HeightField aligned(grid, HeightFieldPlacement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {10.0, 6.0}});
  for (double z : {0.7, 0.3, 0.5}) EXPECT_FALSE(aligned.intersect({1.0, 1.0, z}, {1.0, 0.3, 0.0}));
  // Hits beyond the patch border do not count; nor do hits at or beyond t_max.
  EXPECT_FALSE(aligned.intersect({9.5, 3.0, 1.5}, {1.0, 0.0, -1.0}));
  EXPECT_TRUE(aligned.intersect({8.5, 3.0, 1.5}, {1.0, 0.0, -1.0}));
  EXPECT_FALSE(aligned.intersect({5.0, 3.0, 1.5}, {0.0, 0.0, -1.0}, 1.0));
  // Exactly vertical from below with t_max = inf (the cell's exit t is infinite).
  auto up = aligned.intersect({3.3, 2.2, -1.0}, {0.0, 0.0, 1.0});
  ASSERT_TRUE(up.has_value());
  EXPECT_EQ(up->t, 1.5);
  EXPECT_TRUE(aligned.intersect({5.0, 3.0, 1.5}, {0.0, 0.0, -1.0}, 1.0 + 1e-12));
}

TEST(HeightField, OcclusionAgreesWithNearestHit) {
  HeightFieldGrid grid = random_grid(16, 12, 0.1, 0.1, 7);
  HeightFieldPlacement placement = tilted_placement({3.3, 2.5});
  HeightField field(grid, placement);
  int occluded = 0;
  for (const LocalRay& ray : random_rays(placement.size, 0.1, 85.0, 2000, 8)) {
    glm::dvec3 o = world(placement, ray.o), d = world_direction(placement, ray.d);
    auto hit = field.intersect(o, d);
    if (!hit) {
      EXPECT_FALSE(field.occluded(o, d, kInf));
      continue;
    }
    EXPECT_TRUE(field.occluded(o, d, hit->t * (1.0 + 1e-12)));
    EXPECT_FALSE(field.occluded(o, d, hit->t * (1.0 - 1e-12)));
    ++occluded;
    // A shadow ray from just above the hit towards the ray's origin sees the origin's side
    // unoccluded exactly when the reverse ray hits nothing before the hit point.
    glm::dvec3 start = hit->position + 1e-9 * hit->normal * (glm::dot(d, hit->normal) < 0.0 ? 1.0 : -1.0);
    EXPECT_FALSE(field.occluded(start, -d, hit->t * (1.0 - 1e-6)));
  }
  EXPECT_GT(occluded, 1000);
}

TEST(HeightField, TilesRepeatTheField) {
  // Shifting a ray by whole periods (2 tiles in x, 1 in y) shifts its hit by the same amount.
  HeightFieldGrid grid = random_grid(5, 4, 0.25, 0.2, 9);
  HeightFieldPlacement placement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5.0, 4.0}};
  HeightField field(grid, placement);
  glm::dvec3 shift{2 * 5 * 0.25, 4 * 0.25, 0.0};
  int hits = 0;
  for (const LocalRay& ray : random_rays({1.0, 0.8}, 0.2, 60.0, 300, 10)) {
    auto a = field.intersect(ray.o, ray.d);
    auto b = field.intersect(ray.o + shift, ray.d);
    if (!a || a->position.x < 0.0 || a->position.y < 0.0) continue;  // hits in the first tile only
    ASSERT_TRUE(b.has_value());
    EXPECT_NEAR(a->t, b->t, 1e-12);
    EXPECT_NEAR(a->height, b->height, 1e-13);
    EXPECT_LT(glm::length(a->field_uv - b->field_uv), 1e-12);
    ++hits;
  }
  EXPECT_GT(hits, 100);
}

TEST(HeightField, DegenerateInputs) {
  HeightField field(random_grid(4, 4, 1.0, 0.5, 11),
                    HeightFieldPlacement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {4.0, 4.0}});
  double nan = std::numeric_limits<double>::quiet_NaN();
  glm::dvec3 o{2.0, 2.0, 3.0}, down{0.0, 0.0, -1.0};
  ASSERT_TRUE(field.intersect(o, down));
  EXPECT_FALSE(field.intersect({nan, 2.0, 3.0}, down));
  EXPECT_FALSE(field.intersect(o, {0.0, nan, -1.0}));
  EXPECT_FALSE(field.intersect(o, {0.0, 0.0, 0.0}));
  EXPECT_FALSE(field.intersect(o, down, 0.0));
  EXPECT_FALSE(field.intersect(o, down, -1.0));
  EXPECT_FALSE(field.intersect(o, down, nan));
  EXPECT_FALSE(field.occluded(o, down, nan));
  EXPECT_FALSE(field.intersect({kInf, 2.0, 3.0}, down));
  // A 1 x 1 grid is a constant (tiled) field.
  HeightField single(HeightFieldGrid{1, 1, {0.5}, 0.1, 1.0}, HeightFieldPlacement{});
  auto hit = single.intersect({0.33, 0.77, 2.0}, down);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.5);

  EXPECT_THROW(HeightField(HeightFieldGrid{2, 2, {0, 0, 0}, 1.0, 1.0}, HeightFieldPlacement{}), Error);
  EXPECT_THROW(HeightField(HeightFieldGrid{1, 1, {nan}, 1.0, 1.0}, HeightFieldPlacement{}), Error);
  EXPECT_THROW(HeightField(HeightFieldGrid{1, 1, {0}, 0.0, 1.0}, HeightFieldPlacement{}), Error);
  HeightFieldPlacement skew;
  skew.bitangent = glm::normalize(glm::dvec3(0.1, 1.0, 0.0));
  EXPECT_THROW(HeightField(HeightFieldGrid{1, 1, {0}, 1.0, 1.0}, skew), Error);
  HeightFieldPlacement empty;
  empty.size = {0.0, 1.0};
  EXPECT_THROW(HeightField(HeightFieldGrid{1, 1, {0}, 1.0, 1.0}, empty), Error);
}

TEST(HeightField, ConcurrentQueriesGiveTheSerialAnswers) {
  HeightFieldGrid grid = random_grid(32, 32, 0.05, 0.05, 12);
  HeightFieldPlacement placement = tilted_placement({4.0, 4.0});
  HeightField field(grid, placement);
  std::vector<LocalRay> rays = random_rays(placement.size, 0.05, 80.0, 2000, 13);
  std::vector<double> serial, parallel(rays.size(), -1.0);
  for (const LocalRay& r : rays) {
    auto hit = field.intersect(world(placement, r.o), world_direction(placement, r.d));
    serial.push_back(hit ? hit->t : -2.0);
  }
  auto work = [&](std::size_t begin) {
    for (std::size_t k = begin; k < rays.size(); k += 2) {
      auto hit = field.intersect(world(placement, rays[k].o), world_direction(placement, rays[k].d));
      parallel[k] = hit ? hit->t : -2.0;
    }
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  EXPECT_EQ(serial, parallel);
}

}  // namespace heightfield_test
}  // namespace facet
