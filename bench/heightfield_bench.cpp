// Ray–height-field queries per second on one core: a 512² Gaussian random field (σ_h = 0.5 texel,
// ℓ = 8 texels, tiled 4 × 4 across the patch), rays at several polar angles from the normal, each
// a primary intersect() plus (the *AndShadow cases), on a hit, one occluded() shadow ray towards a
// light at 45°. "Incoherent" rays land anywhere on the patch (every query misses the caches: the
// worst case); "Coherent" rays are in camera scan-line order, 2 pixels per texel, rows of 512
// pixels (what a tile of a rendered image does). The *AndShadow cases also run on 2 threads (both
// cores; items_per_second is then the total, in wall-clock time).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "assets/gaussian_heightfield.hpp"
#include "cpu/heightfield.hpp"

namespace {

const facet::HeightField& field() {
  static const facet::HeightField instance = [] {
    facet::assets::GaussianHeightfieldParams params;
    params.width = params.height = 512;
    params.texel_size = 1.0;
    params.sigma_h = 0.5;
    params.corr_x = params.corr_y = 8.0;
    facet::assets::ScalarField heights = facet::assets::generate_gaussian_heightfield(params);
    return facet::HeightField(
        facet::HeightFieldGrid{512, 512, heights.values, 1.0, 1.0},
        facet::HeightFieldPlacement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2048.0, 2048.0}});
  }();
  return instance;
}

void trace(benchmark::State& state, bool shadow, bool coherent) {
  const facet::HeightField& hf = field();
  double polar = static_cast<double>(state.range(0)) * std::numbers::pi / 180.0;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  glm::dvec3 light = glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
  std::int64_t hits = 0, pixel = 0;
  glm::dvec3 camera_d{std::sin(polar), 0.0, -std::cos(polar)};
  for (auto _ : state) {
    glm::dvec3 d, target;
    if (coherent) {
      d = camera_d;
      std::int64_t px = pixel % 512, py = (pixel / 512) % 2048;
      ++pixel;
      target = {256.0 + 0.5 * (static_cast<double>(px) + uniform(rng)),
                256.0 + 0.5 * (static_cast<double>(py) + uniform(rng)), 0.0};
    } else {
      double azimuth = 2.0 * std::numbers::pi * uniform(rng);
      d = {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), -std::cos(polar)};
      target = {256.0 + 1536.0 * uniform(rng), 256.0 + 1536.0 * uniform(rng), 0.0};
    }
    glm::dvec3 o = target - d * (4.0 / std::max(-d.z, 1e-3));  // starts 4σ_h above the mean plane
    auto hit = hf.intersect(o, d);
    if (hit) {
      ++hits;
      if (shadow) benchmark::DoNotOptimize(hf.occluded(hit->position + 1e-9 * hit->normal, light, 1e30));
    }
    benchmark::DoNotOptimize(hit);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

void BM_IncoherentIntersect(benchmark::State& state) { trace(state, false, false); }
void BM_IncoherentIntersectAndShadow(benchmark::State& state) { trace(state, true, false); }
void BM_CoherentIntersect(benchmark::State& state) { trace(state, false, true); }
void BM_CoherentIntersectAndShadow(benchmark::State& state) { trace(state, true, true); }

}  // namespace

BENCHMARK(BM_IncoherentIntersect)->Arg(0)->Arg(45)->Arg(75)->Arg(89);
BENCHMARK(BM_IncoherentIntersectAndShadow)->Arg(0)->Arg(45)->Arg(75)->Arg(89)->ThreadRange(1, 2)->UseRealTime();
BENCHMARK(BM_CoherentIntersect)->Arg(0)->Arg(45)->Arg(75)->Arg(89);
BENCHMARK(BM_CoherentIntersectAndShadow)->Arg(0)->Arg(45)->Arg(75)->Arg(89)->ThreadRange(1, 2)->UseRealTime();
