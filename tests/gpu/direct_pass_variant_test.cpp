// The direct pass's program variants (gpu/direct_pass_variant.hpp): every scene gets one that
// compiles in all the code it runs, the smallest such, and a scene that mixes families outside
// every smaller variant gets the one with everything, which renders the same bits.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/direct_pass.hpp"
#include "gpu/direct_pass_variant.hpp"
#include "gpu/render_layout.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"
#include "support/frame_difference.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace direct_pass_variant_test {

using gpu::RenderMethod;

const std::vector<std::string> kMethods = {"naive", "mip", "colormip", "filtered", "filtered:table"};

std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes))
    if (entry.path().extension() == ".json" || entry.path().extension() == ".gltf") scenes.push_back(entry.path());
  return scenes;
}

bool covers(const gpu::DirectPassVariant& v, uint32_t code) { return (v.code & code) == code; }

TEST(DirectPassVariants, EveryShippedSceneGetsASmallerVariantThatCoversIt) {
  int fallbacks = 0, renders = 0;
  for (const auto& file : shipped_scenes()) {
    const Scene scene = load_scene(file);
    for (const std::string& name : kMethods) {
      SCOPED_TRACE(file.filename().string() + " " + name);
      const RenderMethod method = RenderMethod::parse(name);
      const uint32_t code = gpu::direct_pass_code(scene, method);
      const gpu::DirectPassVariant& v = gpu::direct_pass_variant(scene, method);
      EXPECT_TRUE(covers(v, code)) << v.name;
      EXPECT_EQ(v.height_fields, gpu::traces_height_fields(scene, method)) << v.name;
      ++renders;
      if (v.code == FACET_CODE_ALL) ++fallbacks;
    }
  }
  // Only the showcase mixes families no one-family variant holds: the every-family variant without the
  // filtered methods takes its naive, mip and colormip, the fallback its filtered and filtered:table.
  EXPECT_EQ(fallbacks, 2);
  EXPECT_EQ(renders, static_cast<int>(shipped_scenes().size() * kMethods.size()));
}

// What each kind of scene needs, from what the scene files hold.
TEST(DirectPassVariants, ScenesNeedTheirFamiliesPrimitivesAndMethods) {
  const auto code = [](const char* scene, const char* method) {
    return gpu::direct_pass_code(load_scene(kScenes / scene), RenderMethod::parse(method));
  };
  EXPECT_EQ(code("colormap_noise_plane.json", "naive"), uint32_t{FACET_CODE_TEXTURE});
  EXPECT_EQ(code("colormap_noise_plane.json", "filtered:table"), uint32_t{FACET_CODE_TEXTURE | FACET_CODE_FILTERED});
  EXPECT_EQ(code("default.json", "filtered"), uint32_t{FACET_CODE_SPHERES | FACET_CODE_TRIANGLES});
  EXPECT_EQ(code("colormap_seams_cube.json", "mip"), uint32_t{FACET_CODE_TEXTURE | FACET_CODE_TRIANGLES});
  EXPECT_EQ(code("microflake_blend.json", "naive"), uint32_t{FACET_CODE_MICROFLAKE | FACET_CODE_SPHERES});
  EXPECT_EQ(code("microflake_blend.json", "filtered:ss:2"),  // the lobe over the pixel
            uint32_t{FACET_CODE_MICROFLAKE | FACET_CODE_SPHERES | FACET_CODE_FILTERED});
  EXPECT_EQ(code("diffraction_plate.json", "naive"),
            uint32_t{FACET_CODE_DIFFRACTION | FACET_CODE_DIFFRACTION_SPECTRAL});
  RenderMethod orders = RenderMethod::parse("naive");
  orders.diffraction.method = diffraction::DiffractionMethod::Orders;
  EXPECT_EQ(gpu::direct_pass_code(load_scene(kScenes / "snake_fingers.json"), orders),
            uint32_t{FACET_CODE_DIFFRACTION | FACET_CODE_DIFFRACTION_SPECTRAL | FACET_CODE_DIFFRACTION_ORDERS |
                     FACET_CODE_TRIANGLES});
  // Where every grating's orders are restricted (the plan knows), `orders` needs no spectral path.
  EXPECT_EQ(gpu::direct_pass_code(load_scene(kScenes / "diffraction_spheres.json"), orders, false),
            uint32_t{FACET_CODE_DIFFRACTION | FACET_CODE_DIFFRACTION_ORDERS | FACET_CODE_SPHERES});
  RenderMethod preintegrated = orders;  // never the spectral path
  preintegrated.diffraction.method = diffraction::DiffractionMethod::Preintegrated;
  EXPECT_EQ(gpu::direct_pass_code(load_scene(kScenes / "diffraction_plate.json"), preintegrated),
            uint32_t{FACET_CODE_DIFFRACTION | FACET_CODE_DIFFRACTION_PREINTEGRATED});
  EXPECT_EQ(code("microsurface_terrain.json", "filtered"), uint32_t{FACET_CODE_MICROSURFACE | FACET_CODE_FILTERED});
  const Scene terrain = load_scene(kScenes / "microsurface_terrain.json");
  EXPECT_TRUE(gpu::direct_pass_variant(terrain, RenderMethod::parse("naive")).height_fields);
  EXPECT_FALSE(gpu::direct_pass_variant(terrain, RenderMethod::parse("colormip")).height_fields);
}

// The choice against a brute-force search of the table, for every combination of code.
TEST(DirectPassVariants, TheSmallestCoveringVariantIsChosenAndMixesGetTheFallback) {
  for (bool fields : {false, true})
    for (uint32_t code = 0; code <= FACET_CODE_ALL; ++code) {
      if (fields && (code & FACET_CODE_MICROSURFACE) == 0) continue;  // only microsurfaces' fields are traced
      const gpu::DirectPassVariant& chosen = gpu::direct_pass_variant(code, fields);
      ASSERT_TRUE(covers(chosen, code)) << code;
      ASSERT_EQ(chosen.height_fields, fields);
      for (const gpu::DirectPassVariant& v : gpu::direct_pass_variants()) {
        if (v.height_fields == fields && covers(v, code)) {
          EXPECT_LE(chosen.spirv.size(), v.spirv.size()) << code << " " << v.name;
        }
      }
    }
  // Mixed families: every family without the filtered methods and preintegrated tables, else everything.
  constexpr uint32_t kEveryFamily = FACET_CODE_ALL & ~(FACET_CODE_FILTERED | FACET_CODE_DIFFRACTION_PREINTEGRATED);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_DIFFRACTION, true).code, kEveryFamily);
  EXPECT_EQ(gpu::direct_pass_variant(
                FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION | FACET_CODE_MICROFLAKE | FACET_CODE_FILTERED, false)
                .code,
            uint32_t{FACET_CODE_ALL});
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_MICROFLAKE | FACET_CODE_TEXTURE, true).code,
            kEveryFamily);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION | FACET_CODE_MICROFLAKE, false).code,
            kEveryFamily);
  // A traced field beside spheres, meshes and textured objects (a ball on rough ground) has programs of its own.
  constexpr uint32_t kFieldAndObjects = FACET_CODE_MICROSURFACE | FACET_CODE_SPHERES | FACET_CODE_TRIANGLES;
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_SPHERES, true).code, kFieldAndObjects);
  EXPECT_EQ(gpu::direct_pass_variant(kFieldAndObjects | FACET_CODE_FILTERED, true).code,
            kFieldAndObjects | FACET_CODE_FILTERED);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_TEXTURE | FACET_CODE_FILTERED, true).code,
            kFieldAndObjects | FACET_CODE_TEXTURE | FACET_CODE_FILTERED);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_TEXTURE | FACET_CODE_SPHERES, false).code,
            kFieldAndObjects | FACET_CODE_TEXTURE);
  // and a grating beside a textured floor, and microflakes beside a traced field.
  constexpr uint32_t kGratingAndTexture = FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION |
                                          FACET_CODE_DIFFRACTION_SPECTRAL | FACET_CODE_DIFFRACTION_ORDERS |
                                          FACET_CODE_SPHERES | FACET_CODE_TRIANGLES;
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION, false).code, kGratingAndTexture);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION | FACET_CODE_FILTERED, false).code,
            kGratingAndTexture | FACET_CODE_FILTERED);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_MICROSURFACE | FACET_CODE_MICROFLAKE | FACET_CODE_FILTERED, true).code,
            kFieldAndObjects | FACET_CODE_MICROFLAKE | FACET_CODE_FILTERED);
  EXPECT_EQ(gpu::direct_pass_variant(FACET_CODE_TEXTURE, false).code, uint32_t{FACET_CODE_TEXTURE});
}

// Unused diffraction and microflake materials put the noise plane outside every smaller variant: the
// fallback renders it, filtered with the error estimate, to the same bits as the textures' own variant.
TEST(DirectPassVariants, TheFallbackRendersTheSameBitsAsTheSmallVariant) {
  auto context = test::make_validated_context();
  const auto file = kScenes / "colormap_noise_plane.json";
  const Scene plain = load_scene(file);
  const Scene mixed =
      load_scene(file, {R"(materials.unused={"type": "diffraction", "grating": {"type": "sinusoid", "period_nm": 1000,
             "amplitude_nm": 100, "size_um": 4, "samples": 16, "coherence_um": 2}})",
                        R"(materials.flakes={"type": "microflake", "ndf": "ggx", "param": 0.3, "albedo": [1, 1, 1]})"});
  RenderMethod method = RenderMethod::parse("filtered");
  method.aovs.error = true;
  ASSERT_EQ(gpu::direct_pass_variant(plain, method).code, uint32_t{FACET_CODE_TEXTURE | FACET_CODE_FILTERED});
  ASSERT_EQ(gpu::direct_pass_variant(mixed, method).code, uint32_t{FACET_CODE_ALL});
  const Image small = gpu::render_direct(*context, plain, 32, 18, method);
  const Image fallback = gpu::render_direct(*context, mixed, 32, 18, method);
  EXPECT_EQ(test::differing_samples(small, fallback), 0);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Mixes of two families that have variants of their own (a ball on rough ground, a grating beside a textured
// floor): rendered, `naive` and `filtered` with the error estimate, to the same bits as by the fallback, which an
// unused material of a third family forces.
struct MixedScene {
  const char* file;
  std::vector<std::string> overrides;
  std::string unused;  // a material of a family outside the mix
};

TEST(DirectPassVariants, MixesWithVariantsOfTheirOwnRenderTheSameBitsAsTheFallback) {
  auto context = test::make_validated_context();
  const std::string ball_on_terrain = R"(objects=[
      {"type": "plane", "point": [0, 0, -1], "normal": [0, 1, 0], "size": [4, 6], "material": "terrain"},
      {"type": "sphere", "center": [0.2, 0.25, -0.6], "radius": 0.25, "material": "ball"}])";
  const std::string unused_grating = R"(materials.unused={"type": "diffraction", "grating": {"type": "sinusoid",
      "period_nm": 1000, "amplitude_nm": 100, "size_um": 4, "samples": 16, "coherence_um": 2}})";
  const std::vector<MixedScene> mixes = {
      {"microsurface_terrain.json",
       {R"(materials.ball={"type": "lambert", "albedo": [0.7, 0.6, 0.5]})", ball_on_terrain},
       unused_grating},
      {"microsurface_terrain.json",
       {R"(materials.ball={"type": "colormap_texture", "texture": {"noise": {"width": 64, "height": 64, "octaves": 3,
            "base_frequency": 4, "seed": 2}}, "colormap": {"builtin": "magma"}})",
        ball_on_terrain},
       unused_grating},
      {"microsurface_terrain.json",
       {R"(materials.ball={"type": "microflake", "ndf": "ggx", "param": 0.3, "albedo": [0.9, 0.7, 0.4]})",
        ball_on_terrain},
       unused_grating},
      {"colormap_noise_plane.json",
       {R"(materials.ball={"type": "diffraction", "grating": {"type": "sinusoid", "period_nm": 1000,
            "amplitude_nm": 120, "size_um": 4, "samples": 16, "coherence_um": 2}, "method": "orders"})",
        R"(objects=[{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": [2, 2], "material": "bands"},
            {"type": "sphere", "center": [0.1, 0.3, -1.2], "radius": 0.3, "material": "ball"}])"},
       R"(materials.unused={"type": "microflake", "ndf": "beckmann", "param": 0.2, "albedo": [0.5, 0.5, 0.5]})"},
  };
  for (const MixedScene& mix : mixes)
    for (const char* name : {"naive", "filtered"}) {
      SCOPED_TRACE(mix.overrides.front().substr(0, 60) + " " + name);
      RenderMethod method = RenderMethod::parse(name);
      method.aovs.error = method.texture == RenderMethod::Texture::Filtered;
      std::vector<std::string> with_unused = mix.overrides;
      with_unused.push_back(mix.unused);
      const Scene small = load_scene(kScenes / mix.file, mix.overrides);
      const Scene fallback_scene = load_scene(kScenes / mix.file, with_unused);
      const gpu::DirectPassVariant& variant = gpu::direct_pass_variant(small, method);
      const gpu::DirectPassVariant& fallback = gpu::direct_pass_variant(fallback_scene, method);
      EXPECT_LT(variant.spirv.size(), fallback.spirv.size()) << variant.name;
      EXPECT_EQ(variant.height_fields, fallback.height_fields);
      const Image alone = gpu::render_direct(*context, small, 40, 24, method);
      const Image with_fallback = gpu::render_direct(*context, fallback_scene, 40, 24, method);
      EXPECT_EQ(test::differing_samples(alone, with_fallback), 0);
    }
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// A periodic grating under `orders` takes a variant without the spectral path; an unused grating without
// orders brings it back (gpu::orders_fall_back), and both render the same bits.
TEST(DirectPassVariants, OrdersWithoutTheSpectralPathRenderTheSameBits) {
  auto context = test::make_validated_context();
  const auto file = kScenes / "diffraction_plate.json";
  const Scene plain = load_scene(file);
  const Scene mixed = load_scene(file, {R"(materials.random={"type": "diffraction", "grating": {"type": "heightmap",
      "path": "gratings/random_heights.exr", "channel": "R", "nm_per_sample": 62.5, "nm_per_unit": 1,
      "coherence_um": 4}, "tolerance": 0.001})"});
  for (const char* name : {"naive", "filtered"}) {
    SCOPED_TRACE(name);
    RenderMethod method = RenderMethod::parse(name);
    method.diffraction.method = diffraction::DiffractionMethod::Orders;
    EXPECT_EQ(gpu::direct_pass_variant(plain, method, false).code & FACET_CODE_DIFFRACTION_SPECTRAL, 0u);
    const Image alone = gpu::render_direct(*context, plain, 48, 48, method);
    const Image with_fallback = gpu::render_direct(*context, mixed, 48, 48, method);
    EXPECT_EQ(test::differing_samples(alone, with_fallback), 0);
    int lit = 0;
    for (size_t i = 0; i < alone.pixel_count(); ++i)
      if (alone.at(i).r > 0.05f) ++lit;
    EXPECT_GT(lit, 0);  // the frame shows diffracted colour, not only the base albedo
  }
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace direct_pass_variant_test
}  // namespace facet
