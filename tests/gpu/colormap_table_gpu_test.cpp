// `filtered:table` on the GPU: colormap_gaussian of the direct pass (probed by
// tests/gpu/shaders/colormap_gaussian_probe.comp over the buffers upload_scene builds) against the
// CPU lookup of the same prefiltered table and against the exact filter, for a step map (the noise
// plane's) and a linear map with a shifted domain; and the spread of the mapped colour around that
// mean (the error estimate's closed form, docs/error_estimate.md eq. 2) against quadrature.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <variant>

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss.hpp>

#include "colormap_gaussian_probe.spv.h"
#include "gpu/render_layout.hpp"
#include "gpu/scene_upload.hpp"
#include "gpu/texture_upload.hpp"
#include "precompute/colormap_filter.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"
#include "vk/kernel.hpp"

namespace facet {
namespace {

using gpu::vec4;

// The noise plane's step map plus a linear map with a shifted domain on the same texture. (A
// 256-point built-in map is tested the same way but its table takes seconds to build:
// docs/colormap_filtering.md.)
Scene two_map_scene() {
  Scene scene = load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/colormap_noise_plane.json");
  const ScalarTexture texture = std::get<ColormapTextureMaterial>(scene.materials.at(0)).texture;
  scene.materials.push_back(ColormapTextureMaterial{
      texture, Colormap({0.0, 0.2, 0.7, 1.0}, {{0.9, 0.2, 0.05}, {0.1, 0.6, 0.8}, {0.3, 0.3, 0.0}, {1.0, 1.0, 1.0}},
                        Colormap::Interpolation::Linear, {0.2, 0.8})});
  scene.material_names.push_back("shifted");
  return scene;
}

// colormap_gaussian on the GPU for probes (mu, sigma, map index, -) by method 3 (filtered) or 4
// (filtered:table), over the buffers of one upload_scene (with tables unless told otherwise).
class GaussianProbe {
 public:
  GaussianProbe(vk::Context& context, const Scene& scene, bool tables = true)
      : context_(&context), buffers_(gpu::upload_scene(context, scene, tables)), pixels_(context, sizeof(vec4)) {}

  std::vector<vec4> run(std::vector<vec4> probes, uint32_t method) {
    vk::Buffer records = vk::Buffer::from(*context_, std::span<const vec4>(probes));
    std::vector<const vk::Buffer*> bindings = buffers_.bindings(pixels_);
    bindings.push_back(&records);
    vk::Kernel kernel(*context_, {.name = "colormap_gaussian_probe",
                                  .spirv = colormap_gaussian_probe_spv,
                                  .buffer_count = static_cast<uint32_t>(bindings.size()),
                                  .push_constant_bytes = sizeof(gpu::GpuTile),
                                  .image_count = 0,
                                  .specialization = {{FACET_RENDER_SPEC_TEXTURE_METHOD, method}},
                                  .buffer_kinds = gpu::SceneBuffers::binding_kinds()});
    const gpu::GpuTile tile{};
    kernel.dispatch(bindings, &tile, {static_cast<uint32_t>((probes.size() + 63) / 64), 1, 1});
    records.download(probes.data(), probes.size() * sizeof(vec4));
    return probes;
  }

 private:
  vk::Context* context_;
  gpu::SceneBuffers buffers_;
  vk::Buffer pixels_;
};

double max_channel(glm::dvec3 d) { return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}); }

// The GPU table against the double lookup of the same table (float bound below) and against the exact
// filter (the table's tolerance plus that bound); below a step map's sigma floor, the exact filter
// itself; extreme inputs finite and within the colours.
TEST(ColormapTableGpu, GpuLookupMatchesTheCpuTableAndTheExactFilter) {
  auto context = test::make_validated_context();
  const Scene scene = two_map_scene();
  std::vector<precompute::PrefilteredColormap> tables;
  std::vector<vec4> probes;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const auto start = std::chrono::steady_clock::now();
    tables.push_back(gpu::build_colormap_table(std::get<ColormapTextureMaterial>(scene.materials[m])));
    const auto& g = tables.back().grid;
    std::printf("table %zu: %dx%d, measured %.2e, built in %.0f ms\n", m, g.mu_count, g.sigma_count,
                tables.back().measured_max_error,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    // mu over the grid and 10% beyond, sigma over [0, sigma_max] (dense at small sigma).
    for (int k = 0; k < 4000; ++k) {
      const double u = unit(rng), s = unit(rng);
      probes.emplace_back(g.mu_min + (g.mu_max - g.mu_min) * (1.2 * u - 0.1), g.sigma_max * s * s, m, 0);
    }
  }
  // Extreme and non-finite moments, checked below for finite colours within the map.
  const float inf = INFINITY, nan = NAN;
  const size_t regular = probes.size();
  for (float m = 0; m < 2; ++m)
    for (float mu : {-1e30f, -5.0f, 0.5f, 5.0f, 1e30f, inf, -inf, nan})
      for (float sigma : {0.0f, 1e-30f, 0.3f, 10.0f, 1e30f, inf, nan}) probes.emplace_back(mu, sigma, m, 0);
  GaussianProbe probe(*context, scene);
  const std::vector<vec4> table = probe.run(probes, 4);
  const std::vector<vec4> exact = probe.run(probes, 3);
  for (size_t i = regular; i < probes.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(table[i][k])) << probes[i].x << " " << probes[i].y;
      EXPECT_GE(table[i][k], 0.0f);
      EXPECT_LE(table[i][k], 1.0f + 1e-5f);
    }
  probes.resize(regular);
  // Float lookup against the double lookup: the cell coordinate u (I - 1) carries ~2 eps_f (I - 1)
  // of rounding (in cells), times the largest node-to-node step (<= 1 here: colours in [0, 1] but
  // the step is far smaller; bound it by the map's colour spread 1), plus ~4 eps_f of blending.
  const double eps_f = std::ldexp(1.0, -24);
  std::vector<double> float_bounds;
  for (const precompute::PrefilteredColormap& t : tables) {
    double step = 0;
    for (int j = 0; j < t.grid.sigma_count; ++j)
      for (int k = 0; k + 1 < t.grid.mu_count; ++k)
        step = std::max(step, max_channel(t.values[j * t.grid.mu_count + k + 1] - t.values[j * t.grid.mu_count + k]));
    float_bounds.push_back(2 * eps_f * (t.grid.mu_count - 1) * step + 8 * eps_f);
  }
  double worst_vs_cpu_table = 0, worst_vs_exact = 0, worst_exact_gpu = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    const size_t m = static_cast<size_t>(probes[i].z);
    const auto& material = std::get<ColormapTextureMaterial>(scene.materials[m]);
    const precompute::PrefilteredColormap& t = tables[m];
    const float mu = probes[i].x, sigma = probes[i].y;
    // The exact GPU loop (knots shared, points beyond 8 sigma skipped) against the double CPU sum:
    // the float kernels' accuracy, 2e-5 (docs/colormap_filtering.md: float twin vs double).
    const double exact_error =
        max_channel(glm::dvec3(exact[i]) - precompute::filtered_colormap_exact(material.colormap, mu, sigma));
    worst_exact_gpu = std::max(worst_exact_gpu, exact_error);
    ASSERT_LE(exact_error, 2e-5) << "map " << m << " mu " << mu << " sigma " << sigma;
    if (sigma < gpu::colormap_table_sigma_floor(material.colormap)) {
      // Below a step map's sigma floor filtered:table is the exact filter itself.
      EXPECT_EQ(table[i], exact[i]) << i;
      continue;
    }
    const double float_bound = float_bounds[m];
    const glm::dvec3 got(table[i]);
    const double vs_table = max_channel(got - t.lookup(mu, sigma));
    const double vs_exact = max_channel(got - precompute::filtered_colormap_exact(material.colormap, mu, sigma));
    worst_vs_cpu_table = std::max(worst_vs_cpu_table, vs_table / float_bound);
    worst_vs_exact = std::max(worst_vs_exact, vs_exact);
    ASSERT_LE(vs_table, float_bound) << "map " << m << " mu " << mu << " sigma " << sigma;
    ASSERT_LE(vs_exact, gpu::kColormapTableTolerance + float_bound)
        << "map " << m << " mu " << mu << " sigma " << sigma;
  }
  std::printf(
      "GPU table vs CPU table: worst %.3f of the float bound; vs exact filter: %.2e (tolerance %.1e); "
      "GPU exact vs CPU exact: %.2e\n",
      worst_vs_cpu_table, worst_vs_exact, gpu::kColormapTableTolerance, worst_exact_gpu);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// The exact GPU loop on a 256-point map (viridis, domain [-1, 2]), where it visits only the points
// within 8 sigma of mu (binary searches): against the double CPU sum over all points, 2e-5.
TEST(ColormapTableGpu, ExactFilterOfALongMapMatchesTheCpu) {
  auto context = test::make_validated_context();
  Scene scene = load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/colormap_noise_plane.json");
  const Colormap map = builtin_colormap("viridis", Colormap::Interpolation::Linear, {-1.0, 2.0});
  scene.materials.at(0) = ColormapTextureMaterial{std::get<ColormapTextureMaterial>(scene.materials[0]).texture, map};
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<vec4> probes;
  for (int k = 0; k < 20000; ++k) {
    const double s = unit(rng);
    probes.emplace_back(-1.5 + 4.0 * unit(rng), 2.0 * std::pow(s, 4), 0, 0);  // sigma from 1e-8 to 2
  }
  const std::vector<vec4> gpu = GaussianProbe(*context, scene, false).run(probes, 3);
  double worst = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    const double error =
        max_channel(glm::dvec3(gpu[i]) - precompute::filtered_colormap_exact(map, probes[i].x, probes[i].y));
    worst = std::max(worst, error);
    ASSERT_LE(error, 2e-5) << "mu " << probes[i].x << " sigma " << probes[i].y;
  }
  std::printf("viridis, GPU exact vs CPU exact: worst %.2e\n", worst);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Extreme and non-finite moments for maps 0 .. maps - 1 (`inside`: a mean within the maps), appended to `probes`.
void add_extreme_probes(std::vector<vec4>& probes, int maps, float inside) {
  const float inf = INFINITY, nan = NAN;
  for (int m = 0; m < maps; ++m)
    for (float mu : {-1e30f, -5.0f, inside, 5.0f, 1e30f, inf, -inf, nan})
      for (float sigma : {0.0f, 1e-30f, 1e4f, 1e20f, 1e30f, inf, nan}) probes.emplace_back(mu, sigma, m, 0);
}

// Every probe from `first` on gives finite colours within its map's colours.
void expect_within_the_colours(const Scene& scene, const std::vector<vec4>& probes, const std::vector<vec4>& gpu,
                               size_t first) {
  for (size_t i = first; i < probes.size(); ++i) {
    const Colormap& map = std::get<ColormapTextureMaterial>(scene.materials.at(size_t(probes[i].z))).colormap;
    for (int k = 0; k < 3; ++k) {
      double lo = INFINITY, hi = -INFINITY;
      for (const glm::dvec3& colour : map.colours()) lo = std::min(lo, colour[k]), hi = std::max(hi, colour[k]);
      EXPECT_TRUE(std::isfinite(gpu[i][k])) << "map " << probes[i].z << " mu " << probes[i].x << " sigma " << probes[i].y;
      EXPECT_GE(gpu[i][k], lo - 1e-6) << "map " << probes[i].z << " mu " << probes[i].x << " sigma " << probes[i].y;
      EXPECT_LE(gpu[i][k], hi + 1e-6) << "map " << probes[i].z << " mu " << probes[i].x << " sigma " << probes[i].y;
    }
  }
}

// Step maps are summed over each lane's own points (eq. K1 of docs/colormap_filtering.md), lanes of different
// maps side by side. Probes cycle through four maps, so every group of 8 lanes that lavapipe runs together
// mixes them: the noise plane's 3-point step map, a 5-point step map with a shifted domain, a 256-point step
// map (viridis, where each lane's walk stops at its first point beyond reach) and a linear map; against the
// double CPU sum, 2e-5 as for one map per group above. Extreme and non-finite mu and sigma give finite colours
// within each map's.
TEST(ColormapTableGpu, LanesOfDifferentMapsInOneSubgroup) {
  auto context = test::make_validated_context();
  Scene scene = two_map_scene();
  const ScalarTexture texture = std::get<ColormapTextureMaterial>(scene.materials.at(0)).texture;
  scene.materials.insert(
      scene.materials.begin() + 1,
      {ColormapTextureMaterial{
           texture, Colormap({0.0, 0.1, 0.15, 0.6, 0.9},
                             {{0.2, 0.4, 0.9}, {1.0, 0.9, 0.1}, {0.0, 0.0, 0.0}, {0.5, 0.1, 0.7}, {0.9, 0.9, 0.9}},
                             Colormap::Interpolation::Steps, {-1.0, 3.0})},
       ColormapTextureMaterial{texture, builtin_colormap("viridis", Colormap::Interpolation::Steps, {-0.5, 1.5})}});
  scene.material_names.insert(scene.material_names.begin() + 1, {"five steps", "viridis steps"});
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<vec4> probes;
  for (int k = 0; k < 16000; ++k) {
    const double s = unit(rng);
    probes.emplace_back(-1.5 + 5.0 * unit(rng), std::pow(s, 4), k % 4, 0);  // sigma from 1e-8 to 1
  }
  const size_t regular = probes.size();
  add_extreme_probes(probes, 4, 0.5f);  // the exact path's step maps too
  const std::vector<vec4> gpu = GaussianProbe(*context, scene, false).run(probes, 3);
  expect_within_the_colours(scene, probes, gpu, regular);
  std::array<double, 4> worst{};
  for (size_t i = 0; i < regular; ++i) {
    const Colormap& map = std::get<ColormapTextureMaterial>(scene.materials.at(size_t(probes[i].z))).colormap;
    const double error =
        max_channel(glm::dvec3(gpu[i]) - precompute::filtered_colormap_exact(map, probes[i].x, probes[i].y));
    worst[size_t(probes[i].z)] = std::max(worst[size_t(probes[i].z)], error);
    ASSERT_LE(error, 2e-5) << "map " << probes[i].z << " mu " << probes[i].x << " sigma " << probes[i].y;
  }
  std::printf("four maps per subgroup, GPU exact vs CPU exact: worst %.2e / %.2e / %.2e / %.2e\n", worst[0], worst[1],
              worst[2], worst[3]);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// The float error of eq. L1 (docs/colormap_filtering.md, "Linear maps as a sum of slopes"), in the map's
// parameter (m, s; points x_k, segment widths h_k). A segment's weight w_k is the difference of g(z) - phi(0)
// at its ends over its standardized width h_k / s; g - phi(0) lies in [-phi(0), 0] and is computed to 8 eps_f
// of phi(0) (exp, coarse tail, products), and to 8 eps_f of |z| where |z| < 0.1 (its series), so w_k carries
// 16 eps_f min(phi(0) s, D_k) / h_k, D_k the farther end's distance from m, plus the coarse tail's 5.3e-7
// (C1, a smooth error that thin segments do not amplify) and eps_f of the rounded z (|dw/dz| <= phi(0)/2).
// w_k is also clamped to [P(t > x_{k+1}), P(t > x_k)], each computed to 7.5e-8 (C1) + 4 eps_f, so its error is
// at most that bracket's width plus twice that: the smaller of the two bounds holds. The positions are rounded
// to float (eps_f/2 for x_k <= 1), which moves c by that times the steepest slope; the sum of the colours adds
// 16 eps_f of the largest.
double linear_sum_float_bound(const Colormap& map, double mu, double sigma) {
  const double eps_f = std::ldexp(1.0, -24), phi0 = 1.0 / std::sqrt(2.0 * std::numbers::pi);
  const glm::dvec2 domain = map.domain();
  const double m = (mu - domain.x) / (domain.y - domain.x), s = sigma / std::abs(domain.y - domain.x);
  const std::vector<double>& x = map.positions();
  const std::vector<glm::dvec3>& c = map.colours();
  const auto above = [&](double position) { return 0.5 * std::erfc((position - m) / std::max(s, 1e-300) / std::sqrt(2.0)); };
  double bound = 0, steepest = 0, largest = 0;
  for (size_t k = 0; k + 1 < x.size(); ++k) {
    const double change = max_channel(c[k + 1] - c[k]), h = x[k + 1] - x[k];
    const double farther = std::max(std::abs(x[k] - m), std::abs(x[k + 1] - m));
    const double rounding = 5.3e-7 + eps_f + 16 * eps_f * std::min(phi0 * s, farther) / h;
    const double bracket = above(x[k]) - above(x[k + 1]) + 2 * (7.5e-8 + 4 * eps_f);
    bound += change * std::min(rounding, bracket);
    steepest = std::max(steepest, change / h);
  }
  for (const glm::dvec3& colour : c) largest = std::max({largest, colour.x, colour.y, colour.z});
  return bound + steepest * eps_f / 2 + 16 * eps_f * largest;
}

// Eq. L1 on the linear maps that stress it: colormap_anisotropic's 5-point map and a map with one segment
// 2^-13 of the domain wide (a near-jump of 0.8) between wide ones; sigma from 1e-8 to 1e3 domain widths, means
// at random and exactly on the points (sigma 0 too, where the point value is continuous); against the double
// CPU sum within linear_sum_float_bound per probe (the double sum's own error, 8 eps_d sigma / h, is below
// 1e-8 here). Extreme and non-finite moments give finite colours within the map's.
TEST(ColormapTableGpu, LinearMapsUnderStressMatchTheCpu) {
  auto context = test::make_validated_context();
  Scene scene = load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/colormap_anisotropic.json");
  const ScalarTexture texture = std::get<ColormapTextureMaterial>(scene.materials.at(0)).texture;
  const double thin = std::ldexp(1.0, -13);
  scene.materials.push_back(ColormapTextureMaterial{
      texture, Colormap({0.0, 0.375, 0.375 + thin, 1.0},
                        {{0.05, 0.1, 0.6}, {0.9, 0.3, 0.1}, {0.1, 0.9, 0.2}, {1.0, 0.95, 0.9}},
                        Colormap::Interpolation::Linear)});
  scene.material_names.push_back("thin segment");
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<vec4> probes;
  for (float m = 0; m < 2; ++m) {
    const Colormap& map = std::get<ColormapTextureMaterial>(scene.materials.at(size_t(m))).colormap;
    ASSERT_EQ(map.domain(), glm::dvec2(0.0, 1.0));  // mu is then the parameter itself, with no rounding
    for (int k = 0; k < 6000; ++k)
      probes.emplace_back(-0.5 + 2.0 * unit(rng), std::pow(10.0, -8.0 + 11.0 * unit(rng)), m, 0);
    for (double x : map.positions())
      for (float sigma : {0.0f, 1e-8f, 1e-5f, 1e-3f, 0.1f, 1.0f, 10.0f, 1e3f}) {
        probes.emplace_back(float(x), sigma, m, 0);
        probes.emplace_back(float(x + thin / 2), sigma, m, 0);  // inside the thin segment, or beside a point
      }
  }
  const size_t regular = probes.size();
  add_extreme_probes(probes, 2, 0.375f);
  const std::vector<vec4> gpu = GaussianProbe(*context, scene, false).run(probes, 3);
  expect_within_the_colours(scene, probes, gpu, regular);
  std::array<double, 2> worst{}, worst_of_bound{};
  std::array<size_t, 2> worst_probe{};
  for (size_t i = 0; i < regular; ++i) {
    const size_t m = size_t(probes[i].z);
    const Colormap& map = std::get<ColormapTextureMaterial>(scene.materials.at(m)).colormap;
    const double error = max_channel(glm::dvec3(gpu[i]) - precompute::filtered_colormap_exact(map, probes[i].x, probes[i].y));
    const double bound = linear_sum_float_bound(map, probes[i].x, probes[i].y);
    if (error > worst[m]) worst[m] = error, worst_probe[m] = i;
    worst_of_bound[m] = std::max(worst_of_bound[m], error / bound);
    ASSERT_LE(error, bound) << "map " << m << " mu " << probes[i].x << " sigma " << probes[i].y;
  }
  for (size_t m = 0; m < 2; ++m)
    std::printf("linear map %zu, GPU exact vs CPU exact: worst %.2e at mu %.6g sigma %.3g; worst %.3f of the bound\n",
                m, worst[m], probes[worst_probe[m]].x, probes[worst_probe[m]].y, worst_of_bound[m]);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Var[c(t)], t ~ N(mu, sigma^2), per channel, by brute force: Gauss-Legendre over pieces of at most
// sigma / 2 on mu +- 10 sigma, cut at the map's knots (c is a polynomial on each piece, the Gaussian
// smooth), mean and second moment from the same nodes.
glm::dvec3 colour_variance_by_quadrature(const Colormap& map, double mu, double sigma) {
  const glm::dvec2 domain = map.domain();
  std::vector<double> cuts = {mu - 10.0 * sigma, mu + 10.0 * sigma};
  for (double p : map.positions()) {
    const double v = domain.x + p * (domain.y - domain.x);
    if (v > cuts[0] && v < cuts[1]) cuts.push_back(v);
  }
  for (double v = cuts[0] + 0.5 * sigma; v < cuts[1]; v += 0.5 * sigma) cuts.push_back(v);
  std::sort(cuts.begin(), cuts.end());
  const double density_scale = 1.0 / (sigma * std::sqrt(2.0 * std::numbers::pi));
  glm::dvec3 first(0.0), second(0.0);
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b > a)) continue;
    for (int channel = 0; channel < 3; ++channel)
      for (int power = 1; power <= 2; ++power) {
        const double integral = boost::math::quadrature::gauss<double, 20>::integrate(
            [&](double t) {
              const double z = (t - mu) / sigma;
              return std::pow(map.at(t)[channel], power) * std::exp(-0.5 * z * z) * density_scale;
            },
            a, b);
        (power == 1 ? first : second)[channel] += integral;
      }
  }
  return second - first * first;
}

// colormap_spread on the GPU (float) squared against the variance by quadrature (double), on a step
// map, a linear map with a shifted domain and viridis as a 256-point linear and step map (lanes of every
// kind side by side), sigma from 1e-3 to 2 domain widths. Float cancellation in
// E[c^2] - E[c]^2 bounds the agreement of the variances, not of their roots: 2e-5 for colours <= 1
// (measured 1.7e-5 with exact knots). The shader's coarse knots (docs/colormap_filtering.md, "Coarse
// knots") move each segment's weight by at most 6e-7, so E[c] by 6e-7 TV(c) and E[c^2] by 6e-7 TV(c^2)
// <= 1.2e-6 TV(c) (colours in [0, 1]); the variance by at most 4 * 6e-7 TV(c), TV the map's total
// variation in its most varying channel. Extreme inputs give finite spreads within the colours.
TEST(ColormapTableGpu, ColourSpreadMatchesQuadrature) {
  auto context = test::make_validated_context();
  Scene scene = two_map_scene();
  // 256-point maps, where each kind's sum visits only the points within reach of the mean.
  const ScalarTexture texture = std::get<ColormapTextureMaterial>(scene.materials.at(0)).texture;
  for (const auto interpolation : {Colormap::Interpolation::Linear, Colormap::Interpolation::Steps}) {
    scene.materials.push_back(ColormapTextureMaterial{texture, builtin_colormap("viridis", interpolation, {-0.5, 1.5})});
    scene.material_names.push_back(interpolation == Colormap::Interpolation::Linear ? "viridis" : "viridis steps");
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<vec4> probes;
  for (int m = 0; m < 4; ++m)
    for (int k = 0; k < 60; ++k)
      probes.emplace_back(-0.2 + 1.4 * unit(rng), std::pow(10.0, -3.0 + 3.3 * unit(rng)), m, 1);
  const size_t regular = probes.size();
  for (int m = 0; m < 4; ++m)
    for (float mu : {-1e30f, 0.5f, 1e30f})
      for (float sigma : {0.0f, 1e-30f, 10.0f, 1e30f}) probes.emplace_back(mu, sigma, m, 1);
  const std::vector<vec4> spread = GaussianProbe(*context, scene, false).run(probes, 3);
  const auto total_variation = [](const Colormap& map) {
    glm::dvec3 variation(0.0);
    for (size_t k = 0; k + 1 < map.colours().size(); ++k)
      variation += glm::abs(map.colours()[k + 1] - map.colours()[k]);
    return std::max({variation.x, variation.y, variation.z});
  };
  double worst = 0;
  for (size_t i = 0; i < regular; ++i) {
    const auto& material = std::get<ColormapTextureMaterial>(scene.materials.at(static_cast<size_t>(probes[i].z)));
    const glm::dvec3 variance = colour_variance_by_quadrature(material.colormap, probes[i].x, probes[i].y);
    const glm::dvec3 gpu = glm::dvec3(spread[i]);
    const double error = max_channel(gpu * gpu - variance);
    worst = std::max(worst, error);
    const double bound = 2e-5 + 4 * 6e-7 * total_variation(material.colormap);
    ASSERT_LE(error, bound) << "map " << probes[i].z << " mu " << probes[i].x << " sigma " << probes[i].y;
  }
  for (size_t i = regular; i < probes.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(std::isfinite(spread[i][c]) && spread[i][c] >= 0.0f && spread[i][c] <= 1.0f)
          << "mu " << probes[i].x << " sigma " << probes[i].y << ": " << spread[i][c];
  std::printf("colour spread, GPU squared vs quadrature variance: worst %.2e\n", worst);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Within one step of a step map and 3 to 12 sigma from its jumps the colour is nearly constant: the spread
// is that of the tails beyond the jumps (quadrature). The GPU's is within 2e-5 of it (the mean's float
// rounding, ~1e-7, and the coarse knots' relative error in the tails), not off by the cancellation of
// E[c^2] - mean^2 (~1e-7 of c^2, a spread of ~3e-4), which would rank such pixels among the erring ones,
// nor by a tail's weight taken as the difference of two probabilities near 1 (~6e-8 each, a spread of
// ~2e-4 where the tails are 5 sigma away).
TEST(ColormapTableGpu, ColourSpreadWithinAStepIsZero) {
  auto context = test::make_validated_context();
  const Scene scene = two_map_scene();
  const Colormap& steps = std::get<ColormapTextureMaterial>(scene.materials.at(0)).colormap;
  ASSERT_EQ(steps.interpolation(), Colormap::Interpolation::Steps);
  const double width = steps.domain().y - steps.domain().x;
  std::vector<vec4> probes;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (size_t k = 0; k + 1 < steps.positions().size(); ++k) {
    const double gap = steps.positions()[k + 1] - steps.positions()[k];
    for (int i = 0; i < 40; ++i) {
      const double sigma = gap / (6.0 + 18.0 * unit(rng));  // the middle at 3-12 sigma from each jump
      const double middle = steps.positions()[k] + gap * (0.5 + 0.02 * (unit(rng) - 0.5));
      probes.emplace_back(steps.domain().x + middle * width, sigma * width, 0, 1);
    }
  }
  const std::vector<vec4> spread = GaussianProbe(*context, scene, false).run(probes, 3);
  double worst = 0.0;
  for (size_t i = 0; i < probes.size(); ++i) {
    const glm::dvec3 exact = glm::sqrt(glm::max(colour_variance_by_quadrature(steps, probes[i].x, probes[i].y), 0.0));
    const double error = max_channel(glm::abs(glm::dvec3(spread[i]) - exact));
    worst = std::max(worst, error);
    EXPECT_LE(error, 2e-5) << "mu " << probes[i].x << " sigma " << probes[i].y;
  }
  std::printf("colour spread within a step, GPU vs quadrature: worst %.2e\n", worst);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace
}  // namespace facet
