// The reference renderer: exact agreement with the direct CPU pass where both apply, unbiasedness
// against analytic answers (linear colour maps, a step map over a measured texture histogram, a flat
// height field, overhead views of a height field), determinism across thread counts, convergence
// of the N×N jittered grid, and interruption.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

#include "assets/fbm_noise.hpp"
#include "assets/gaussian_heightfield.hpp"
#include "common/error.hpp"
#include "cpu/direct_cpu.hpp"
#include "cpu/reference_renderer.hpp"
#include "kernels/shared.hpp"
#include "reference_test_scenes.hpp"
#include "scene/camera_frame.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"

namespace facet {
namespace {

Image render(const Scene& scene, int w, int h, int grid, bool jitter = true, int threads = 0, std::uint64_t seed = 1) {
  cpu::ReferenceOptions o;
  o.width = w;
  o.height = h;
  o.grid = grid;
  o.jitter = jitter;
  o.threads = threads;
  o.seed = seed;
  return cpu::render_reference(scene, o);
}

double mean_channel(const Image& image, int c) {
  double sum = 0.0;
  for (std::size_t p = 0; p < image.pixel_count(); ++p) sum += image.at(p)[c];
  return sum / static_cast<double>(image.pixel_count());
}

// Bilinear interpolation of a periodic grid at texel coordinates (x, y), texel centres at integers:
// written here independently of the renderer's sampler.
double bilinear(const assets::ScalarField& f, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto i = static_cast<long long>(fx), j = static_cast<long long>(fy);
  const double u = x - fx, v = y - fy;
  return (1 - u) * (1 - v) * f.wrapped(i, j) + u * (1 - v) * f.wrapped(i + 1, j) + (1 - u) * v * f.wrapped(i, j + 1) +
         u * v * f.wrapped(i + 1, j + 1);
}

std::shared_ptr<const assets::ScalarField> noise(int side, std::uint64_t seed) {
  assets::FbmParams p;
  p.width = p.height = side;
  p.octaves = 4;
  p.seed = seed;
  return std::make_shared<const assets::ScalarField>(assets::generate_fbm_noise(p).field);
}

// An overhead plane textured with `texture` through `map`, lit so that radiance = albedo.
Scene textured_plane(std::shared_ptr<const assets::ScalarField> texture, Colormap map, double uv_scale, double fov) {
  Scene s;
  s.camera = test::overhead_camera(1.0, fov, 32);
  test::unit_lighting(s, false);
  s.materials = {ColormapTextureMaterial{std::move(texture), std::move(map)}};
  s.material_names = {"t"};
  Plane p;
  p.uv_scale = glm::dvec2(uv_scale);
  s.planes = {p};
  return s;
}

TEST(ReferenceRenderer, GridOneWithoutJitterEqualsTheDirectCpuPass) {
  for (const char* name : {"default.json", "microflake_blend.json"}) {
    const Scene scene = load_scene(kScenes / name);
    const Image direct = cpu::render_direct_cpu(scene, 64, 36);
    const Image reference = render(scene, 64, 36, 1, false);
    EXPECT_EQ(reference.rgb, direct.rgb) << name;  // same rays, same kernels, same double arithmetic
  }
}

TEST(ReferenceRenderer, IdenticalForAnyThreadCount) {
  for (const char* name : {"colormap_noise_plane.json", "microsurface_glossy.json"}) {
    const Scene scene = load_scene(kScenes / name);
    const Image one = render(scene, 24, 14, 3, true, 1, 7);
    const Image two = render(scene, 24, 14, 3, true, 2, 7);
    EXPECT_EQ(one.rgb, two.rgb) << name;
    const Image other_seed = render(scene, 24, 14, 3, true, 2, 8);
    EXPECT_NE(one.rgb, other_seed.rgb) << name;  // the seed does reach the jitter
  }
}

TEST(ReferenceRenderer, LinearColormapGivesTheFilteredMean) {
  // Lambert is linear in the albedo, so with a linear map a + (b − a) t every pixel must be
  // a + (b − a) · (the pixel of the identity map): the mean of t over the same samples.
  const auto texture = noise(64, 3);
  const glm::dvec3 a(0.1, 0.7, 0.2), b(0.9, 0.3, 0.6);
  const Scene identity = textured_plane(
      texture, Colormap({0.0, 1.0}, {glm::dvec3(0.0), glm::dvec3(1.0)}, Colormap::Interpolation::Linear), 3.0, 60.0);
  const Scene linear =
      textured_plane(texture, Colormap({0.0, 1.0}, {a, b}, Colormap::Interpolation::Linear), 3.0, 60.0);
  const Image t = render(identity, 32, 32, 4), c = render(linear, 32, 32, 4);
  double worst = 0.0;
  for (std::size_t p = 0; p < t.pixel_count(); ++p)
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(c.at(p)[k] - (a[k] + (b[k] - a[k]) * t.at(p)[k])));
  // Both images are stored as float: a few float ulp of values <= 1.
  RecordProperty("worst", testing::PrintToString(worst));
  EXPECT_LT(worst, 3e-7);
}

TEST(ReferenceRenderer, StepColormapSeesTheTextureHistogram) {
  // Each pixel covers ~14 texture tiles, so every pixel's expected value is the fraction of the
  // tile where the bilinear texture is >= 0.5; measured here on a 16× finer grid of the texture.
  const auto texture = noise(64, 5);
  double above = 0.0;
  const int fine = 16 * 64;
  for (int j = 0; j < fine; ++j)
    for (int i = 0; i < fine; ++i) above += bilinear(*texture, (i + 0.5) / 16.0, (j + 0.5) / 16.0) >= 0.5;
  above /= static_cast<double>(fine) * fine;
  const Image image = render(textured_plane(texture, test::step_map(0.5), 400.0, 60.0), 32, 32, 6);
  // 36 864 jittered samples of a 0/1 variable: standard error <= 0.5/192 = 0.0026; 4 sigma.
  RecordProperty("measured", std::to_string(mean_channel(image, 0)) + " vs " + std::to_string(above));
  EXPECT_NEAR(mean_channel(image, 0), above, 0.011);
  EXPECT_GT(above, 0.2);  // the test means something: neither colour dominates
  EXPECT_LT(above, 0.8);
}

// The Beckmann microfacet BRDF · cos_i written out independently (Walter et al. 2007, with the Smith
// height-correlated G2 and the erf form of Λ), for the flat field.
double beckmann_f_cos(glm::dvec3 wi, glm::dvec3 wo, glm::dvec2 alpha) {
  const auto lambda = [&](glm::dvec3 w) {
    const double a = w.z / std::sqrt(alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y);
    return 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(std::numbers::pi));
  };
  const glm::dvec3 h = glm::normalize(wi + wo);
  const double d = std::exp(-(h.x * h.x / (alpha.x * alpha.x) + h.y * h.y / (alpha.y * alpha.y)) / (h.z * h.z)) /
                   (std::numbers::pi * alpha.x * alpha.y * std::pow(h.z, 4));
  return d / (1.0 + lambda(wi) + lambda(wo)) / (4.0 * wo.z);
}

TEST(ReferenceRenderer, FlatHeightFieldGivesTheUnmaskedAnswer) {
  Scene s;
  s.camera = {{0.3, 1.2, 1.5}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 40.0, 24, 16};
  s.light = {glm::normalize(glm::dvec3(-0.4, 1.0, -0.7)), {2.0, 2.5, 3.0}};
  s.ambient = {0.1, 0.2, 0.3};
  MicrosurfaceMaterial m;
  m.heights = std::make_shared<const assets::ScalarField>(assets::ScalarField{8, 8, std::vector<double>(64, 0.0)});
  m.texel_size = 0.05;
  m.height_colormap = builtin_colormap("viridis", Colormap::Interpolation::Linear, {-1.0, 3.0});
  m.specular = BeckmannSpecular{{0.15, 0.4}, {0.5, 0.6, 0.7}};
  s.materials = {m};
  s.material_names = {"flat"};
  Plane p;
  p.tangent = glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
  p.size = glm::dvec2(10.0, 10.0);
  s.planes = {p};

  const Image image = render(s, 24, 16, 1, false);
  const CameraFrame cam = camera_frame(s.camera, 24, 16);
  const glm::dvec3 albedo = m.height_colormap->at(0.0);
  const glm::dvec3 t = p.tangent, n(0, 1, 0), b = glm::cross(n, t), l = s.light.direction;
  const glm::dvec3 wi(glm::dot(l, t), glm::dot(l, b), glm::dot(l, n));
  double worst = 0.0;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 24; ++x) {
      const glm::dvec3 d = kernels::f64::camera_ray_direction(cam.forward, cam.right, cam.up,
                                                              glm::dvec2(x + 0.5, y + 0.5), glm::dvec2(24, 16));
      const glm::dvec3 v = -d, wo(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n));
      const glm::dvec3 expected =
          albedo / std::numbers::pi * (s.light.irradiance * wi.z + s.ambient) +
          s.light.irradiance * m.specular->reflectance * beckmann_f_cos(wi, wo, m.specular->alpha);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(image.at(x, y)[k] - expected[k]) / expected[k]);
    }
  }
  // Float storage (6e-8) plus the f64 kernels' Λ against erf (1e-14): 1e-6 leaves room for neither to hide.
  RecordProperty("worst", testing::PrintToString(worst));
  EXPECT_LT(worst, 1e-6);
}

// A height-coloured Gaussian field with snow (white) from z >= 0 and black below, lit by ambient
// only, so that a pixel's value is the fraction of the surface it sees that lies above z = 0.
Scene snow_field(const Camera& camera) {
  Scene s;
  s.camera = camera;
  test::unit_lighting(s, true);
  assets::GaussianHeightfieldParams g;
  g.width = g.height = 64;
  g.texel_size = 0.002;  // a period of 0.128 world units: every footprint below spans several
  g.sigma_h = 0.002;
  g.corr_x = g.corr_y = 0.008;
  g.seed = 4;
  MicrosurfaceMaterial m;
  m.heights = std::make_shared<const assets::ScalarField>(assets::generate_gaussian_heightfield(g));
  m.texel_size = g.texel_size;
  m.height_colormap = test::step_map(0.5, {-1.0, 1.0});  // t = (z + 1)/2 >= 0.5 <=> z >= 0
  s.materials = {m};
  s.material_names = {"snow"};
  Plane p;
  p.tangent = {1.0, 0.0, 0.0};
  p.size = glm::dvec2(20.0, 20.0);
  s.planes = {p};
  return s;
}

TEST(ReferenceRenderer, OverheadViewOfAHeightFieldSeesItsAreaFractionAndGrazingHidesTheValleys) {
  // Straight down, the film maps affinely onto the plane and nothing is masked: the expected image
  // mean is the area fraction of z >= 0 over the footprint, measured here on a fine grid with an
  // independent bilinear interpolation (heights at texel corners = vertices, period 64 texels).
  const double h = 2.0, fov = 20.0;
  const Scene overhead = snow_field(test::overhead_camera(h, fov, 32));
  const auto& field = *std::get<MicrosurfaceMaterial>(overhead.materials[0]).heights;
  const double half = h * std::tan(glm::radians(fov) / 2.0);  // footprint half-width, world units
  // Patch coordinates of the footprint: x = world x + 10, y = −world z + 10 (origin at the corner).
  double above = 0.0;
  const int n = 1024;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = 10.0 - half + 2.0 * half * (i + 0.5) / n, y = 10.0 - half + 2.0 * half * (j + 0.5) / n;
      above += bilinear(field, x / 0.002, y / 0.002) >= 0.0;
    }
  }
  above /= static_cast<double>(n) * n;
  const double seen_overhead = mean_channel(render(overhead, 32, 32, 4), 0);
  // 16 384 stratified samples of a 0/1 variable: 0.01 is 2.5 sigma of the unstratified bound and far
  // above what the stratification leaves.
  EXPECT_NEAR(seen_overhead, above, 0.01);

  // 1 to 11 degrees above the horizon (the footprint spans ~20 periods in depth) the slopes (rms 0.35
  // per axis, 19 degrees) hide the valleys behind the peaks.
  const Camera grazing{{0.0, 0.05, 8.0}, {0.0, 0.0, 8.0 - 0.05 / std::tan(glm::radians(6.0))}, {0, 1, 0}, 10.0, 32, 32};
  const double seen_grazing = mean_channel(render(snow_field(grazing), 32, 32, 4), 0);
  RecordProperty("measured",
                 std::to_string(above) + " " + std::to_string(seen_overhead) + " " + std::to_string(seen_grazing));
  EXPECT_GT(seen_grazing, seen_overhead + 0.15);
}

TEST(ReferenceRenderer, ErrorOfTheJitteredGridFallsFasterThanMonteCarlo) {
  // Pixels with hard colour edges (a step map): the stratified estimator's RMS error falls like
  // N^-1.5 (edges cross O(N) of the N² strata), plain Monte Carlo like N^-1. Reference: N = 64.
  const Scene scene = textured_plane(noise(64, 9), test::step_map(0.5), 1.5, 60.0);
  const Image reference = render(scene, 16, 16, 64, true, 0, 1000);
  std::vector<double> errors;
  for (int n : {2, 4, 8, 16}) {
    const Image image = render(scene, 16, 16, n, true, 0, static_cast<std::uint64_t>(n));
    double sum2 = 0.0;
    for (std::size_t p = 0; p < image.pixel_count(); ++p) sum2 += std::pow(image.at(p).r - reference.at(p).r, 2);
    errors.push_back(std::sqrt(sum2 / static_cast<double>(image.pixel_count())));
  }
  RecordProperty("errors", std::to_string(errors[0]) + " " + std::to_string(errors[1]) + " " +
                               std::to_string(errors[2]) + " " + std::to_string(errors[3]));
  for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]);
  const double slope = std::log(errors.back() / errors.front()) / std::log(8.0);  // over N = 2 ... 16
  EXPECT_LT(slope, -1.2) << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3];
  EXPECT_GT(slope, -2.2);  // and no faster than a smooth integrand would allow: the edges are there
}

TEST(ReferenceRenderer, InterruptionThrowsAndInvalidOptionsAreErrors) {
  const Scene scene = load_scene(kScenes / "default.json");
  std::atomic<bool> cancel{true};
  cpu::ReferenceOptions o;
  o.width = 16;
  o.height = 16;
  o.cancel = &cancel;
  try {
    cpu::render_reference(scene, o);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "interrupted; no file written");
  }
  o.cancel = nullptr;
  o.grid = 0;
  EXPECT_THROW(cpu::render_reference(scene, o), Error);
}

TEST(ReferenceRenderer, ShippedScenesRenderFiniteAtLowResolution) {
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    const Scene scene = load_scene(entry.path());
    const Image image = render(scene, 16, 9, 1);
    // Spectral colours of diffraction materials outside the sRGB gamut have negative linear components
    // (docs/diffraction.md, "Rendering"); everything else is non-negative.
    const bool spectral = std::any_of(scene.materials.begin(), scene.materials.end(),
                                      [](const Material& m) { return std::holds_alternative<DiffractionMaterial>(m); });
    for (float v : image.rgb) ASSERT_TRUE(std::isfinite(v) && (spectral || v >= 0.0f)) << entry.path();
  }
}

TEST(ReferenceRenderer, JitterIsUniformAndDecorrelated) {
  // Mean 1/2 and variance 1/12 per axis, zero covariance, over 2^16 (pixel, sample) pairs.
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  const int count = 1 << 16;
  for (int i = 0; i < count; ++i) {
    const glm::dvec2 u =
        cpu::reference_jitter(1, static_cast<std::uint64_t>(i / 64), static_cast<std::uint64_t>(i % 64));
    ASSERT_TRUE(u.x >= 0.0 && u.x < 1.0 && u.y >= 0.0 && u.y < 1.0);
    sx += u.x, sy += u.y, sxx += u.x * u.x, syy += u.y * u.y, sxy += u.x * u.y;
  }
  const double mx = sx / count, my = sy / count;
  // Standard errors: 0.0011 for the means, 0.0003 for the (co)variances; bounds are 4-5 sigma.
  EXPECT_NEAR(mx, 0.5, 0.005);
  EXPECT_NEAR(my, 0.5, 0.005);
  EXPECT_NEAR(sxx / count - mx * mx, 1.0 / 12.0, 0.0015);
  EXPECT_NEAR(syy / count - my * my, 1.0 / 12.0, 0.0015);
  EXPECT_NEAR(sxy / count - mx * my, 0.0, 0.0015);
}

}  // namespace
}  // namespace facet
