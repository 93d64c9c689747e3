// The GPU tracer's bound on visited MIP nodes (renderer/gpu/heightfield_trace_bound.hpp) against brute
// force: the nodes a segment of the field passes through, level by level, found by walking it in small
// steps; and the longest segment of a ray within the heights' range over the rectangle, found by casting
// rays in double and cutting them as the tracer does.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "gpu/heightfield_trace_bound.hpp"
#include "scene/plane_frame.hpp"

namespace facet {
namespace {

MicrosurfaceMaterial field(int width, int height, double texel_size, double amplitude) {
  auto values = std::make_shared<assets::ScalarField>();
  values->width = width;
  values->height = height;
  values->values.resize(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < values->values.size(); ++i) values->values[i] = amplitude * std::sin(0.37 * i);
  MicrosurfaceMaterial m;
  m.heights = values;
  m.texel_size = texel_size;
  return m;
}

// Distinct nodes (tile, level, node) that the segment from a to b (texels over the rectangle) passes
// through, at every level of a w x h tile's MIP chain, walked in steps of 1/32 texel.
std::int64_t nodes_passed(int w, int h, glm::dvec2 a, glm::dvec2 b) {
  std::set<std::tuple<int, int, int, int, int>> seen;
  const int steps = static_cast<int>(std::ceil(glm::length(b - a) * 32.0)) + 1;
  for (int i = 0; i <= steps; ++i) {
    const glm::dvec2 p = a + (b - a) * (static_cast<double>(i) / steps);
    const int tx = static_cast<int>(std::floor(p.x / w)), ty = static_cast<int>(std::floor(p.y / h));
    const int x = static_cast<int>(std::floor(p.x)) - tx * w, y = static_cast<int>(std::floor(p.y)) - ty * h;
    for (int l = 0; (1 << l) < 2 * std::max(w, h); ++l) seen.emplace(tx, ty, l, x >> l, y >> l);
  }
  return static_cast<std::int64_t>(seen.size());
}

TEST(HeightFieldTraceBound, NodesOfASegmentStayWithinTheBound) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto& [w, h] : {std::pair{37, 91}, std::pair{64, 64}, std::pair{256, 16}}) {
    const MicrosurfaceMaterial m = field(w, h, 1.0, 1.0);
    const glm::dvec2 size(5.5 * w, 3.25 * h);  // tiles, the last ones cut
    for (double length : {0.5, 3.0, 17.0, 100.0, 700.0}) {
      const std::int64_t bound = gpu::heightfield_trace_nodes(m, size, length);
      std::int64_t worst = 0;
      for (int trial = 0; trial < 100; ++trial) {
        const double phi = 6.283185307179586 * unit(rng);
        const glm::dvec2 d(std::cos(phi), std::sin(phi));
        glm::dvec2 a(unit(rng) * size.x, unit(rng) * size.y);
        glm::dvec2 b = a + length * d;
        b = glm::clamp(b, glm::dvec2(0.0), size - 1e-9);  // cut to the rectangle: no longer than `length`
        a = glm::clamp(a, glm::dvec2(0.0), size - 1e-9);
        worst = std::max(worst, nodes_passed(w, h, a, b));
      }
      std::printf("%dx%d length %.1f: worst %lld, bound %lld\n", w, h, length, static_cast<long long>(worst),
                  static_cast<long long>(bound));
      EXPECT_LE(worst, bound) << w << "x" << h << " length " << length;
      // Not far above what segments of that length pass through (so it lifts the old refusals).
      if (length >= 17.0) {
        EXPECT_LT(bound, 4 * worst + 16 * 12) << w << "x" << h << " length " << length;
      }
    }
    // Unbounded length: the whole rectangle's columns and rows, per level.
    EXPECT_EQ(gpu::heightfield_trace_nodes(m, size, std::numeric_limits<double>::infinity()),
              gpu::heightfield_trace_nodes(m, size, 1e12));
  }
}

// The segment of o + t d within [lo, hi] along the plane's normal and over its rectangle, its length across
// the plane (0 if none), as render/heightfield_trace.glsl cuts a ray.
double segment_across(const Plane& plane, double lo, double hi, glm::dvec3 o, glm::dvec3 d) {
  const PlaneFrame f = plane_frame(plane);
  const glm::dvec3 rel = o - plane.point;
  const glm::dvec3 ro(glm::dot(rel, f.tangent), glm::dot(rel, f.bitangent), glm::dot(rel, f.normal));
  const glm::dvec3 rd(glm::dot(d, f.tangent), glm::dot(d, f.bitangent), glm::dot(d, f.normal));
  double t0 = 0.0, t1 = 1e300;
  const auto slab = [&](double o1, double d1, double a, double b) {
    if (d1 == 0.0) {
      if (o1 < a || o1 > b) t1 = -1.0;
      return;
    }
    double ta = (a - o1) / d1, tb = (b - o1) / d1;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  };
  slab(ro.x, rd.x, -0.5 * plane.size->x, 0.5 * plane.size->x);
  slab(ro.y, rd.y, -0.5 * plane.size->y, 0.5 * plane.size->y);
  slab(ro.z, rd.z, lo, hi);
  return t1 > t0 ? (t1 - t0) * std::hypot(rd.x, rd.y) : 0.0;
}

Plane tilted_rectangle() {
  Plane p;
  p.point = {0.3, -0.2, 1.0};
  p.normal = glm::normalize(glm::dvec3(0.1, 1.0, 0.25));
  p.tangent = {1.0, 0.0, 0.0};
  p.size = glm::dvec2(3.0, 5.0);
  return p;
}

TEST(HeightFieldTraceBound, CameraRaysCrossTheHeightsWithinTheirPath) {
  const Plane plane = tilted_rectangle();
  const double lo = -0.004, hi = 0.006;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const PlaneFrame f = plane_frame(plane);
  for (double height : {0.05, 0.4, 3.0, -0.3}) {
    const glm::dvec3 camera = plane.point + height * f.normal + 2.0 * f.tangent - 3.5 * f.bitangent;
    const double bound = gpu::heightfield_camera_ray_path(plane, lo, hi, camera);
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {  // toward points of the range over the rectangle, and a little beyond
      const glm::dvec3 target = plane.point + (unit(rng) - 0.5) * 3.2 * f.tangent +
                                (unit(rng) - 0.5) * 5.2 * f.bitangent + (lo + (hi - lo) * unit(rng)) * f.normal;
      worst = std::max(worst, segment_across(plane, lo, hi, camera, glm::normalize(target - camera)));
    }
    EXPECT_LE(worst, bound) << "camera " << height << " above the plane";
    EXPECT_GT(worst, 0.5 * bound) << "camera " << height << " above the plane";
  }
  // Within the heights' range a ray may run along the plane: no bound but the rectangle.
  EXPECT_TRUE(std::isinf(gpu::heightfield_camera_ray_path(plane, lo, hi, plane.point + 0.001 * f.normal)));
}

TEST(HeightFieldTraceBound, ShadowRaysCrossTheHeightsWithinTheirPath) {
  const Plane plane = tilted_rectangle();
  const double lo = -0.004, hi = 0.006;
  const PlaneFrame f = plane_frame(plane);
  for (double elevation_deg : {2.0, 15.0, 60.0, 89.0}) {
    const double e = elevation_deg * 3.14159265358979 / 180.0;
    const glm::dvec3 l = std::cos(e) * glm::normalize(f.tangent + 0.5 * f.bitangent) + std::sin(e) * f.normal;
    const double bound = gpu::heightfield_directed_ray_path(plane, lo, hi, l, 1.0);
    // From the bottom of the range at the rectangle's centre: the longest a shadow ray runs in it.
    const double longest = segment_across(plane, lo, hi, plane.point + lo * f.normal, l);
    EXPECT_LE(longest, bound) << elevation_deg;
    EXPECT_GT(longest, 0.99 * bound) << elevation_deg;
  }
  // Along the plane (its normal component a rounding error): longer than any rectangle.
  EXPECT_GT(gpu::heightfield_directed_ray_path(plane, lo, hi, f.tangent, 1.0), 1e9);
  EXPECT_TRUE(
      std::isinf(gpu::heightfield_directed_ray_path(plane, lo, hi, f.normal, std::numeric_limits<double>::infinity())));
}

// A scene's shadow rays start at its geometry: an infinite plane not parallel to the field's reaches any
// height, so the bound falls back to the whole rectangle; a parallel one does not.
TEST(HeightFieldTraceBound, InfinitePlanesAcrossTheFieldLeaveShadowRaysUnbounded) {
  Scene s;
  s.materials = {field(64, 64, 0.001, 0.002), LambertMaterial{}};
  s.camera.position = {0.0, 1.0, 3.0};
  s.light.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  Plane rectangle;
  rectangle.size = glm::dvec2(4.0, 4.0);
  s.planes = {rectangle};
  const auto& m = std::get<MicrosurfaceMaterial>(s.materials[0]);
  const std::int64_t full = gpu::heightfield_trace_nodes(m, *rectangle.size, std::numeric_limits<double>::infinity());
  const std::int64_t alone = gpu::heightfield_shadow_nodes(s);
  EXPECT_LT(alone, full / 20);
  EXPECT_LT(gpu::heightfield_camera_nodes(s, s.camera.position), full / 3);
  Plane ground;
  ground.point = {0.0, -0.5, 0.0};
  ground.material = 1;
  s.planes.push_back(ground);
  EXPECT_EQ(gpu::heightfield_shadow_nodes(s), alone);
  s.planes.back().normal = glm::normalize(glm::dvec3(0.0, 1.0, 0.1));
  EXPECT_EQ(gpu::heightfield_shadow_nodes(s), full);
}

}  // namespace
}  // namespace facet
