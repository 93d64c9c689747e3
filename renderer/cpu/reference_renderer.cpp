#include "cpu/reference_renderer.hpp"

#include <limits>
#include <mutex>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "common/error.hpp"
#include "cpu/diffraction_shading.hpp"
#include "cpu/material_shading.hpp"
#include "cpu/reference_scene.hpp"
#include "kernels/shared.hpp"
#include "scene/camera_frame.hpp"

namespace facet::cpu {

namespace {

namespace k = kernels::f64;

// splitmix64's finaliser (Steele, Lea and Flood 2014): a bijection of 64-bit words that mixes every
// input bit into every output bit.
std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double unit_interval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }  // [0, 1)

class PixelIntegrator {
 public:
  PixelIntegrator(const Scene& scene, const ReferenceScene& world, const DiffractionShading& diffracted,
                  const ReferenceOptions& options)
      : scene_(scene),
        world_(world),
        diffracted_(diffracted),
        options_(options),
        camera_(camera_frame(scene.camera, options.width, options.height)),
        resolution_(options.width, options.height) {}

  // The box-filtered mean over the N×N grid of pixel (x, y): radiance in rgb, coverage (the fraction of
  // the rays that hit geometry) in a; and, where options.aovs asks, the auxiliary outputs into `aov`.
  glm::dvec4 pixel(int x, int y, AovPixel& aov) const {
    const int n = options_.grid;
    const auto index = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(options_.width) + x;
    glm::dvec4 sum(0.0);
    AovSums aov_sums;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const glm::dvec2 offset = options_.jitter
                                      ? reference_jitter(options_.seed, index, static_cast<std::uint64_t>(j) * n + i)
                                      : glm::dvec2(0.5);
        const glm::dvec2 film(x + (i + offset.x) / n, y + (j + offset.y) / n);
        const auto sample = static_cast<std::uint64_t>(j) * n + i;
        sum += radiance(k::camera_ray_direction(camera_.forward, camera_.right, camera_.up, film, resolution_),
                        wavelength_sample(index, sample), options_.aovs.any() ? &aov_sums : nullptr);
      }
    }
    if (options_.aovs.any()) aov = aov_sums.mean();
    return sum / (static_cast<double>(n) * n);
  }

 private:
  // Each of the N x N samples of a pixel gets its own wavelength: stratum (s P + pixel offset) mod N^2
  // of [0, 1), a permutation (P = 7919 is prime, N <= 4096) that decouples the wavelength stratum
  // from the sample's position, jittered within the stratum (docs/diffraction.md, "Exact reference").
  double wavelength_sample(std::uint64_t pixel, std::uint64_t sample) const {
    const std::uint64_t strata = static_cast<std::uint64_t>(options_.grid) * options_.grid;
    const std::uint64_t stratum = (sample * 7919u + mix64(options_.seed ^ pixel) % strata) % strata;
    const double jitter = options_.jitter ? reference_jitter(~options_.seed, pixel, sample).x : 0.5;
    return (static_cast<double>(stratum) + jitter) / static_cast<double>(strata);
  }

  // Depth, normal and uv summed over a pixel's rays that hit geometry (docs/aov.md): their means are
  // the pixel's, the normal renormalised, as the GPU pass reports them.
  struct AovSums {
    int hits = 0;
    double depth = 0.0;
    glm::dvec3 normal{0.0};
    glm::dvec2 uv{0.0};
    AovPixel mean() const {
      AovPixel p;
      p.depth = hits > 0 ? static_cast<float>(depth / hits) : std::numeric_limits<float>::infinity();
      if (hits > 0 && glm::dot(normal, normal) > 0.0) p.normal = glm::vec3(glm::normalize(normal));
      if (hits > 0) p.uv = glm::vec2(uv / static_cast<double>(hits));
      return p;
    }
  };

  // Radiance along d (rgb), and 1 if it hit geometry, else 0 (a); the hit's auxiliary values added to
  // `aov` if given: camera-space z, the normal (toward the ray) and the uv of a macro-surface.
  glm::dvec4 radiance(glm::dvec3 d, double wavelength_u, AovSums* aov) const {
    const auto hit = world_.intersect(camera_.origin, d);
    if (!hit) return glm::dvec4(scene_.background, 0.0);
    if (aov) {
      ++aov->hits;
      aov->depth += hit->t * glm::dot(d, camera_.forward);
      aov->normal += hit->normal;
      if (!hit->micro) aov->uv += hit->uv;
    }
    return glm::dvec4(shade(*hit, d, wavelength_u), 1.0);
  }

  // Radiance leaving `hit` along -d.
  glm::dvec3 shade(const SurfaceHit& hit, glm::dvec3 d, double wavelength_u) const {
    const glm::dvec3 l = scene_.light.direction;
    const double visibility =
        glm::dot(hit.normal, l) > 0.0 && world_.occluded(world_.shadow_origin(hit), l) ? 0.0 : 1.0;
    const Material& material = scene_.materials[hit.material];
    if (!hit.micro) {
      glm::dvec3 c = shade_macro_surface(scene_, material, hit.normal, -d, hit.uv, visibility);
      if (diffracted_.handles(hit.material))
        c += diffracted_.radiance_at(hit.material, hit.normal, hit.back_face, hit.dpdu, -d, visibility, wavelength_u);
      return c;
    }
    const auto& m = std::get<MicrosurfaceMaterial>(material);
    glm::dvec3 c = k::lambert_radiance(microsurface_albedo(m, hit.height, hit.slope), hit.normal, l,
                                       scene_.light.irradiance, visibility, scene_.ambient);
    if (m.specular)
      c += beckmann_specular_radiance(*m.specular, hit.normal, hit.tangent, -d, l, scene_.light.irradiance,
                                      visibility);
    return c;
  }

  const Scene& scene_;
  const ReferenceScene& world_;
  const DiffractionShading& diffracted_;
  const ReferenceOptions& options_;
  CameraFrame camera_;
  glm::dvec2 resolution_;
};

void validate(const ReferenceOptions& o) {
  if (o.width < 1 || o.height < 1) throw Error("reference: image size must be positive");
  if (o.grid < 1 || o.grid > 4096) throw Error("reference: grid must be in [1, 4096], got " + std::to_string(o.grid));
  if (o.threads < 0) throw Error("reference: threads must be >= 0");
  if (o.tile_size < 1) throw Error("reference: tile size must be positive");
}

}  // namespace

glm::dvec2 reference_jitter(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample) {
  const std::uint64_t h = mix64(mix64(mix64(seed) ^ pixel) ^ sample);
  return {unit_interval(h), unit_interval(mix64(h))};
}

Image render_reference(const Scene& scene, const ReferenceOptions& options) {
  validate(options);
  const ReferenceScene world(scene);
  const DiffractionShading diffracted(scene, DiffractionShading::Transform::Exact);
  const PixelIntegrator integrator(scene, world, diffracted, options);
  const int ts = options.tile_size;
  const int tiles_x = (options.width + ts - 1) / ts, tiles_y = (options.height + ts - 1) / ts;
  const std::int64_t tiles = static_cast<std::int64_t>(tiles_x) * tiles_y;
  const auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed); };

  if (options.aovs.error)
    throw Error(
        "--aov error: the reference writes no error estimate (it is the truth the estimate is checked against)");
  Image image(options.width, options.height);
  image.alpha.resize(image.pixel_count());
  const std::size_t first_aov = add_aov_channels(image, options.aovs);
  std::mutex progress_mutex;
  std::int64_t done = 0;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::int64_t>(0, tiles, 1),
        [&](const tbb::blocked_range<std::int64_t>& range) {
          for (std::int64_t tile = range.begin(); tile != range.end(); ++tile) {
            const int x0 = static_cast<int>(tile % tiles_x) * ts, y0 = static_cast<int>(tile / tiles_x) * ts;
            for (int y = y0; y < std::min(y0 + ts, options.height) && !cancelled(); ++y)
              for (int x = x0; x < std::min(x0 + ts, options.width); ++x) {
                AovPixel aov;
                const glm::dvec4 pixel = integrator.pixel(x, y, aov);
                image.set(x, y, glm::vec3(pixel));
                image.alpha[image.index(x, y)] = static_cast<float>(pixel.a);
                set_aov_pixel(image, options.aovs, first_aov, image.index(x, y), aov);
              }
            if (options.progress) {
              const std::lock_guard lock(progress_mutex);
              options.progress(++done, tiles);
            }
          }
        },
        tbb::simple_partitioner());
  });
  if (cancelled()) throw Error("interrupted; no file written");
  return image;
}

}  // namespace facet::cpu
