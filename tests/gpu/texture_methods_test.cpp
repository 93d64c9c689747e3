// The GPU methods for colour-mapped textures (naive, mip, colormip, ss:K, filtered) against the
// CPU reference (renderer/cpu/reference_renderer.hpp) on the grazing noise-plane scene, where
// MIP-mapping before the colour map goes visibly wrong.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "cpu/reference_renderer.hpp"
#include "gpu/direct_pass.hpp"
#include "gpu/texture_upload.hpp"
#include "image/metrics.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

constexpr int kWidth = 64, kHeight = 36;

Scene noise_plane() { return load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/colormap_noise_plane.json"); }

cpu::ReferenceOptions reference_options(int grid, bool jitter) {
  cpu::ReferenceOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.grid = grid;
  options.jitter = jitter;
  options.seed = 7;
  return options;
}

Image render(vk::Context& context, const Scene& scene, const std::string& method, int w = kWidth, int h = kHeight) {
  return gpu::render_direct(context, scene, w, h, gpu::RenderMethod::parse(method));
}

double fraction_within(const Image& a, const Image& b, double tolerance) {
  size_t within = 0;
  for (size_t i = 0; i < a.pixel_count(); ++i) {
    glm::dvec3 d = glm::abs(glm::dvec3(a.at(i)) - glm::dvec3(b.at(i)));
    within += std::max({d.x, d.y, d.z}) <= tolerance;
  }
  return static_cast<double>(within) / a.pixel_count();
}

// `naive` is the reference's estimator with one sample at the pixel centre: the same rays, texel
// lookups and colour map, in float. The step colour map flips where float and double texture
// values straddle a step, on a few per cent of the pixels of this high-frequency scene.
TEST(TextureMethods, NaiveMatchesTheReferenceAtPixelCentres) {
  auto context = test::make_validated_context();
  Scene scene = noise_plane();
  Image gpu = render(*context, scene, "naive");
  Image cpu = cpu::render_reference(scene, reference_options(1, false));
  EXPECT_GE(fraction_within(gpu, cpu, 1e-4), 0.95);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Against a 16x16 jittered reference: `filtered` must beat `naive` (aliasing) and `mip` (colour map
// of the mean texture value: the far field turns to the map's middle colour) by far. On a static
// texture `colormip` is the box-filtered truth up to the footprint's shape; `filtered` (a mixture of
// per-tap Gaussians of the texture values over a finer tiling of the footprint, here a 3-band step map
// over fBm) must beat it and 4x4 supersampling; measured 64x36: naive 0.27, mip 0.22, colormip 0.029,
// ss:4 0.057, filtered 0.022 (0.041 with one Gaussian of the pooled moments).
TEST(TextureMethods, FilteredBeatsTheBaselinesAgainstTheReference) {
  auto context = test::make_validated_context();
  Scene scene = noise_plane();
  Image reference = cpu::render_reference(scene, reference_options(16, true));
  double error[5];
  const char* methods[] = {"naive", "mip", "colormip", "ss:4", "filtered"};
  for (int i = 0; i < 5; ++i) error[i] = rmse(render(*context, scene, methods[i]), reference);
  std::printf("RMSE vs 16x16 reference: naive %.4f mip %.4f colormip %.4f ss:4 %.4f filtered %.4f\n", error[0],
              error[1], error[2], error[3], error[4]);
  EXPECT_LT(error[4], 0.5 * error[0]);
  EXPECT_LT(error[4], 0.5 * error[1]);
  EXPECT_LT(error[3], error[0]);  // supersampling converges toward the reference
  EXPECT_LT(error[4], error[2]);
  EXPECT_LT(error[4], error[3]);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Seen from close up, every pixel footprint is smaller than a texel. `filtered` then models the
// footprint's values by the bilinear texture linearised over it (variance (w^2/12)|grad t|^2 for a
// footprint w texels wide), so it equals `naive` up to the colour map's curvature over a few sigma:
// exactly (float rounding) where the step map is constant over mu +- 6 sigma, and it antialiases the
// colour steps, which brings it closer to the reference than `naive` there. Measured (32x32): 93.2% of
// pixels within 1e-5 of naive; RMSE vs a 16x16 reference naive 0.0353, filtered 0.0046.
TEST(TextureMethods, FilteredEqualsNaiveUnderMagnificationExceptAtColourSteps) {
  auto context = test::make_validated_context();
  Scene scene = noise_plane();
  scene.camera.position = {0.0, 0.05, 0.0};
  scene.camera.target = {0.0, 0.0, -0.02};
  scene.camera.fov_y_deg = 40.0;
  Image naive = render(*context, scene, "naive", 32, 32);
  Image filtered = render(*context, scene, "filtered", 32, 32);
  cpu::ReferenceOptions options = reference_options(16, true);
  options.width = options.height = 32;
  Image reference = cpu::render_reference(scene, options);
  const double same = fraction_within(filtered, naive, 1e-5);
  const double e_naive = rmse(naive, reference), e_filtered = rmse(filtered, reference);
  std::printf("magnified: %.1f%% of pixels equal naive; RMSE naive %.4f filtered %.4f\n", 100 * same, e_naive,
              e_filtered);
  EXPECT_GE(same, 0.9);
  EXPECT_LT(e_filtered, e_naive);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// filtered:table looks the same Gaussians up in the prefiltered table (kColormapTableTolerance per
// colour channel, above the step map's sigma floor; exact below it): the images differ by at most that
// tolerance times the largest shading factor (E cos/pi + ambient/pi <= (3 + 0.3)/pi here) plus float rounding.
TEST(TextureMethods, FilteredTableMatchesFilteredWithinTheTableTolerance) {
  auto context = test::make_validated_context();
  Scene scene = noise_plane();
  Image exact = render(*context, scene, "filtered");
  Image table = render(*context, scene, "filtered:table");
  const double bound = gpu::kColormapTableTolerance * (3.0 + 0.3) / 3.14159265358979 + 1e-5;
  const double worst = max_abs_error(table, exact);
  std::printf("filtered:table vs filtered: max %.2e (bound %.2e)\n", worst, bound);
  EXPECT_LE(worst, bound);
  EXPECT_GT(worst, 0.0);  // the table path is really taken
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(TextureMethods, UnknownMethodIsAnError) {
  EXPECT_THROW(gpu::RenderMethod::parse("bilinear"), Error);
  EXPECT_THROW(gpu::RenderMethod::parse("ss:0"), Error);
  EXPECT_THROW(gpu::RenderMethod::parse("ss:17"), Error);
  EXPECT_EQ(gpu::RenderMethod::parse("ss:8").name(), "ss:8");
  EXPECT_EQ(gpu::RenderMethod::parse("filtered").name(), "filtered");
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:table").name(), "filtered:table");
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:table").texture, gpu::RenderMethod::Texture::FilteredTable);
  EXPECT_THROW(gpu::RenderMethod::parse("filtered:"), Error);
}

// M:ss:K: footprint method M per stratum; the text survives a round trip and K keeps ss:K's range.
TEST(TextureMethods, FootprintMethodsPerStratum) {
  const gpu::RenderMethod filtered = gpu::RenderMethod::parse("filtered:ss:3");
  EXPECT_EQ(filtered.texture, gpu::RenderMethod::Texture::Filtered);
  EXPECT_EQ(filtered.samples_per_axis, 3);
  for (const char* text : {"filtered:ss:2", "filtered:table:ss:4", "colormip:ss:16", "mip:ss:2"})
    EXPECT_EQ(gpu::RenderMethod::parse(text).name(), text);
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:ss:1").name(), "filtered");
  for (const char* text :
       {"filtered:ss:0", "filtered:ss:17", "filtered:ss:", "filtered:ss:2x", "naive:ss:2", "ss:2:ss:2"})
    EXPECT_THROW(gpu::RenderMethod::parse(text), Error) << text;
}

}  // namespace
}  // namespace facet
