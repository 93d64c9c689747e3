// The prefiltered table T(mu, sigma) (renderer/precompute/prefiltered_colormap.cpp, lookup math in
// shaders/lib/colormap_table.glsl): its bilinear lookup against the exact filter on dense pseudo-random
// points that are not the builder's probes, the float lookup against the double one, and the clamping
// of out-of-range inputs. Table sizes and measured errors are recorded as test properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "kernels/shared.hpp"
#include "precompute/colormap_filter.hpp"
#include "precompute/prefiltered_colormap.hpp"

namespace prefiltered_colormap_test {

using facet::Colormap;
using facet::precompute::PrefilteredColormap;
namespace k32 = facet::kernels::f32;

std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// Max channel error of the lookup over n points: mu uniform over the grid plus 10% beyond each end,
// sigma = sigma_max u^2 (dense where T changes fastest), sigma >= sigma_floor.
double dense_error(const Colormap& map, const PrefilteredColormap& table, int n, double sigma_floor = 0.0) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double span = table.grid.mu_max - table.grid.mu_min;
  double worst = 0;
  for (int s = 0; s < n; ++s) {
    const double mu = table.grid.mu_min - 0.1 * span + 1.2 * span * unit(rng);
    const double u = unit(rng);
    const double sigma = std::max(sigma_floor, table.grid.sigma_max * u * u);
    const glm::dvec3 d = glm::abs(table.lookup(mu, sigma) - facet::precompute::filtered_colormap_exact(map, mu, sigma));
    worst = std::max({worst, d.x, d.y, d.z});
  }
  return worst;
}

// A continuous (linear) map: the tolerance holds everywhere, sigma = 0 included. Built-in viridis
// (256 points, nodes on its control points) at 1e-2 and an uneven 4-point map with a domain [2, 6]
// (kinks between nodes: the sigma = 0 row needs a fine mu step) at 1e-3 up to sigma = 0.5.
TEST(PrefilteredColormap, LinearMapsMeetTheToleranceOnDensePoints) {
  struct Case {
    Colormap map;
    facet::precompute::PrefilteredColormapOptions options;
  };
  const Case cases[] = {
      {facet::builtin_colormap("viridis"), {1e-2}},
      {Colormap({0.0, 0.1, 0.65, 1.0}, {{0.9, 0.2, 0.05}, {0.1, 0.6, 0.8}, {0.3, 0.3, 0.0}, {1.0, 1.0, 1.0}},
                Colormap::Interpolation::Linear, {2.0, 6.0}),
       {1e-3, 0.5}}};
  int index = 0;
  for (const Case& c : cases) {
    const PrefilteredColormap table = facet::precompute::build_prefiltered_colormap(c.map, c.options);
    const double dense = dense_error(c.map, table, 20000);
    const std::string tag = "case" + std::to_string(index++);
    RecordProperty(tag + "_size", std::to_string(table.grid.mu_count) + "x" + std::to_string(table.grid.sigma_count));
    RecordProperty(tag + "_probed_error", sci(table.measured_max_error));
    RecordProperty(tag + "_dense_error", sci(dense));
    EXPECT_LE(table.measured_max_error, c.options.tolerance);
    EXPECT_LE(dense, c.options.tolerance) << tag;
  }
}

// A step map cannot be interpolated across its jumps as sigma -> 0 (the error there is up to half a
// jump whatever the spacing): with sigma_floor = 0.02 the tolerance holds above the floor, and below
// it the error is indeed large (the reason the renderer filters exactly there).
TEST(PrefilteredColormap, StepMapMeetsTheToleranceAboveItsSigmaFloor) {
  const Colormap map({0.0, 0.3, 0.5, 1.0}, {{0.9, 0.2, 0.05}, {0.1, 0.6, 0.8}, {0.3, 0.3, 0.0}, {1.0, 1.0, 1.0}},
                     Colormap::Interpolation::Steps);
  const PrefilteredColormap table = facet::precompute::build_prefiltered_colormap(map, {1e-3, 0.0, 0.02});
  const double above = dense_error(map, table, 20000, 0.02);
  const double below = dense_error(map, table, 20000);
  RecordProperty("size", std::to_string(table.grid.mu_count) + "x" + std::to_string(table.grid.sigma_count));
  RecordProperty("probed_error", sci(table.measured_max_error));
  RecordProperty("dense_error_above_floor", sci(above));
  RecordProperty("dense_error_whole_range", sci(below));
  EXPECT_LE(table.measured_max_error, 1e-3);
  EXPECT_LE(above, 1e-3);
  EXPECT_GT(below, 1e-2);
}

// The float lookup (f32 grid, RGBA float values: what the GPU reads) against the double one. The cell
// coordinate x = u (I - 1) carries ~2 eps_f (I - 1) of rounding (in cells), which moves the result by
// that times the largest node-to-node difference; values and blending add ~2 eps_f.
TEST(PrefilteredColormap, FloatLookupMatchesDouble) {
  const Colormap map = facet::builtin_colormap("magma");
  const PrefilteredColormap table = facet::precompute::build_prefiltered_colormap(map, {1e-2});
  double step = 0;  // largest difference between neighbouring nodes, per channel
  for (int j = 0; j < table.grid.sigma_count; ++j)
    for (int i = 0; i + 1 < table.grid.mu_count; ++i) {
      const glm::dvec3 d =
          glm::abs(table.values[(j * table.grid.mu_count) + i + 1] - table.values[(j * table.grid.mu_count) + i]);
      step = std::max({step, d.x, d.y, d.z});
    }
  const double eps_f = 1.2e-7;
  const double tolerance = 2 * eps_f * (table.grid.mu_count - 1) * step + 4 * eps_f;
  const k32::ColormapTableGrid grid = table.grid_f32();
  const std::vector<glm::vec4> rgba = table.rgba_f32();
  double worst = 0;
  for (float mu = -0.5f; mu <= 1.5f; mu += 0.00731f)
    for (float sigma = 0.0f; sigma <= 0.6f; sigma += 0.0137f) {
      const k32::ColormapTableTaps taps = k32::colormap_table_taps(grid, mu, sigma);
      auto at = [&](int di, int dj) {
        return glm::vec3(rgba[k32::colormap_table_index(grid, taps.i0 + di, taps.j0 + dj)]);
      };
      const glm::vec3 f = k32::colormap_table_blend(at(0, 0), at(1, 0), at(0, 1), at(1, 1), taps);
      const glm::dvec3 d = glm::abs(glm::dvec3(f) - table.lookup(mu, sigma));
      worst = std::max({worst, d.x, d.y, d.z});
    }
  RecordProperty("worst_abs_f32", sci(worst));
  RecordProperty("tolerance", sci(tolerance));
  EXPECT_LT(worst, tolerance);
}

// Out of range and non-finite inputs land on the grid's edges: the end colours, finite, never NaN.
TEST(PrefilteredColormap, ExtremeInputsClampToTheGrid) {
  const Colormap map = facet::builtin_colormap("magma");
  const PrefilteredColormap table = facet::precompute::build_prefiltered_colormap(map, {1e-2});
  const glm::dvec3 first = map.colours().front(), last = map.colours().back();
  for (double sigma : {0.0, 1e-30, 1e-3}) {
    const glm::dvec3 below = table.lookup(-1e30, sigma), above = table.lookup(1e30, sigma);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(below[i], first[i], 1e-2 / 4);
      EXPECT_NEAR(above[i], last[i], 1e-2 / 4);
    }
  }
  const double nan = std::nan(""), inf = INFINITY;
  for (double mu : {nan, -inf, inf, 0.5})
    for (double sigma : {nan, -1.0, 1e300, inf}) {
      const glm::dvec3 v = table.lookup(mu, sigma);
      for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(v[i])) << mu << " " << sigma;
    }
}

}  // namespace prefiltered_colormap_test
