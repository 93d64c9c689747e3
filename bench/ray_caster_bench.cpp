// Throughput of the CPU ray caster (one thread) on scenes/default.json: primary rays of a
// 320 x 180 pinhole view, and shadow rays toward the light from the points they hit.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "cpu/ray_caster.hpp"
#include "scene/scene_loader.hpp"

namespace {

struct Ray {
  glm::dvec3 o, d;
};

std::vector<Ray> primary_rays(const facet::Camera& c, int width, int height) {
  const glm::dvec3 w = glm::normalize(c.target - c.position);
  const glm::dvec3 u = glm::normalize(glm::cross(w, c.up)), v = glm::cross(u, w);
  const double h = std::tan(glm::radians(c.fov_y_deg) / 2.0), aspect = double(width) / height;
  std::vector<Ray> rays;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double sx = (2.0 * (x + 0.5) / width - 1.0) * h * aspect, sy = (1.0 - 2.0 * (y + 0.5) / height) * h;
      rays.push_back({c.position, glm::normalize(w + sx * u + sy * v)});
    }
  }
  return rays;
}

const facet::Scene& default_scene() {
  static const facet::Scene scene = facet::load_scene(FACET_SOURCE_DIR "/scenes/default.json");
  return scene;
}

void BM_PrimaryRays(benchmark::State& state) {
  const facet::RayCaster caster(default_scene());
  const std::vector<Ray> rays = primary_rays(default_scene().camera, 320, 180);
  for (auto _ : state) {
    for (const Ray& r : rays) benchmark::DoNotOptimize(caster.intersect(r.o, r.d));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(rays.size()));
}
BENCHMARK(BM_PrimaryRays)->Unit(benchmark::kMillisecond);

void BM_ShadowRays(benchmark::State& state) {
  const facet::RayCaster caster(default_scene());
  std::vector<Ray> shadow;
  for (const Ray& r : primary_rays(default_scene().camera, 320, 180)) {
    if (const auto h = caster.intersect(r.o, r.d)) {
      shadow.push_back({h->position + 1e-9 * h->geometric_normal, default_scene().light.direction});
    }
  }
  for (auto _ : state) {
    for (const Ray& r : shadow) benchmark::DoNotOptimize(caster.occluded(r.o, r.d, 1e30));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(shadow.size()));
}
BENCHMARK(BM_ShadowRays)->Unit(benchmark::kMillisecond);

}  // namespace
