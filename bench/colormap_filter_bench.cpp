// Gaussian colour-map filtering per evaluation: the exact segment sum (double, and float = the GPU's
// arithmetic) against the prefiltered table lookup, for maps of K control points.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <vector>

#include "kernels/shared.hpp"
#include "precompute/colormap_filter.hpp"
#include "precompute/prefiltered_colormap.hpp"

namespace {

using facet::Colormap;

// K evenly spaced points of a smooth ramp.
Colormap ramp(int k) {
  std::vector<double> x(static_cast<std::size_t>(k));
  std::vector<glm::dvec3> c(x.size());
  for (int i = 0; i < k; ++i) {
    const double t = static_cast<double>(i) / (k - 1);
    x[static_cast<std::size_t>(i)] = t;
    c[static_cast<std::size_t>(i)] = {t * t, 0.5 + 0.4 * std::sin(6.0 * t), 1.0 - t};
  }
  return Colormap(std::move(x), std::move(c), Colormap::Interpolation::Linear);
}

// (mu, sigma) pairs cycling over the map and the footprint widths a renderer sees.
std::vector<glm::dvec2> inputs() {
  std::vector<glm::dvec2> v;
  for (int i = 0; i < 1024; ++i)
    v.emplace_back(-0.2 + 1.4 * ((i * 37) % 1024) / 1024.0, 0.3 * ((i * 11) % 64) / 64.0 * ((i * 11) % 64) / 64.0);
  return v;
}

const facet::precompute::PrefilteredColormap& table(int k) {
  static std::map<int, std::unique_ptr<facet::precompute::PrefilteredColormap>> tables;
  auto& t = tables[k];
  if (!t)
    t = std::make_unique<facet::precompute::PrefilteredColormap>(
        facet::precompute::build_prefiltered_colormap(ramp(k), {1e-2}));
  return *t;
}

void BM_ExactF64(benchmark::State& state) {
  const Colormap map = ramp(static_cast<int>(state.range(0)));
  const std::vector<glm::dvec2> in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::dvec2 p = in[i++ & 1023];
    benchmark::DoNotOptimize(facet::precompute::filtered_colormap_exact(map, p.x, p.y));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ExactF32(benchmark::State& state) {
  const Colormap map = ramp(static_cast<int>(state.range(0)));
  const std::vector<glm::dvec2> in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::vec2 p(in[i++ & 1023]);
    benchmark::DoNotOptimize(facet::precompute::filtered_colormap_exact_f32(map, p.x, p.y));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_TableF64(benchmark::State& state) {
  const facet::precompute::PrefilteredColormap& t = table(static_cast<int>(state.range(0)));
  const std::vector<glm::dvec2> in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::dvec2 p = in[i++ & 1023];
    benchmark::DoNotOptimize(t.lookup(p.x, p.y));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_TableF32(benchmark::State& state) {
  namespace k32 = facet::kernels::f32;
  const facet::precompute::PrefilteredColormap& t = table(static_cast<int>(state.range(0)));
  const k32::ColormapTableGrid grid = t.grid_f32();
  const std::vector<glm::vec4> rgba = t.rgba_f32();
  const std::vector<glm::dvec2> in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::vec2 p(in[i++ & 1023]);
    const k32::ColormapTableTaps taps = k32::colormap_table_taps(grid, p.x, p.y);
    auto at = [&](int di, int dj) {
      return glm::vec3(rgba[k32::colormap_table_index(grid, taps.i0 + di, taps.j0 + dj)]);
    };
    benchmark::DoNotOptimize(k32::colormap_table_blend(at(0, 0), at(1, 0), at(0, 1), at(1, 1), taps));
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_ExactF64)->Arg(4)->Arg(16)->Arg(64)->Arg(256);
BENCHMARK(BM_ExactF32)->Arg(4)->Arg(16)->Arg(64)->Arg(256);
BENCHMARK(BM_TableF64)->Arg(4)->Arg(16)->Arg(64)->Arg(256);
BENCHMARK(BM_TableF32)->Arg(4)->Arg(16)->Arg(64)->Arg(256);

}  // namespace
