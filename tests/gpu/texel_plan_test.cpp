// The scene upload reserves its texels ahead (gpu/scene_upload.cpp): what it plans for each material
// (microsurface_texels, colormap_texture_texels) must be what the material then appends, for square,
// odd and thin fields, and after other materials' texels. And what a colour-mapped texture appends is
// laid out as the render pass reads it (moments as pairs).
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "gpu/microsurface_upload.hpp"
#include "gpu/texture_upload.hpp"
#include "precompute/moment_mips.hpp"
#include "scene/colormap.hpp"

namespace facet {
namespace texel_plan_test {  // named: the unity build joins this file with others

std::shared_ptr<const assets::ScalarField> random_field(int width, int height, unsigned seed) {
  auto field = std::make_shared<assets::ScalarField>();
  field->width = width;
  field->height = height;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < width * height; ++k) field->values.push_back(u(rng));
  return field;
}

struct Size {
  int width, height;
};
constexpr Size kSizes[] = {{256, 256}, {37, 23}, {2, 2}, {1, 5}, {64, 3}, {200, 120}};

TEST(TexelPlan, MicrosurfacesAppendThePlannedTexels) {
  gpu::TextureData data;
  unsigned seed = 1;
  for (const Size s : kSizes) {
    MicrosurfaceMaterial m;
    m.heights = random_field(s.width, s.height, seed++);
    m.texel_size = 0.01;
    m.height_scale = 0.05;
    m.height_colormap = builtin_colormap("viridis");
    const std::size_t before = data.texels.size();
    gpu::add_microsurface(data, m);
    EXPECT_EQ(data.texels.size() - before, gpu::microsurface_texels(m)) << s.width << "x" << s.height;
  }
}

TEST(TexelPlan, ColormapTexturesAppendThePlannedTexels) {
  gpu::TextureData data;
  unsigned seed = 1;
  for (const Size s : kSizes) {
    ColormapTextureMaterial m{random_field(s.width, s.height, seed++), builtin_colormap("magma")};
    const std::size_t before = data.texels.size();
    gpu::add_colormap_texture(data, m);
    EXPECT_EQ(data.texels.size() - before, gpu::colormap_texture_texels(m)) << s.width << "x" << s.height;
  }
}

// Level 0 of a texture's moments holds in texel (x, y) the pair (E[t], E[t^2] + within-texel variance) of
// itself and of (x + 1 mod width, y), the texels a bilinear lookup reads (render/texture_sampling.glsl),
// and its chain is built as pairs; the colour-mapped chain keeps one texel per texel.
TEST(TexelPlan, ColormapTextureMomentsArePairsWithTheRightNeighbour) {
  unsigned seed = 7;
  for (const Size s : kSizes) {
    gpu::TextureData data;
    ColormapTextureMaterial m{random_field(s.width, s.height, seed++), builtin_colormap("magma")};
    const gpu::uvec4 texture = gpu::add_colormap_texture(data, m);
    ASSERT_EQ(data.gpu_chains.size(), 2u);
    EXPECT_EQ(data.gpu_chains[0].first, texture.x);
    EXPECT_EQ(data.gpu_chains[0].layout, gpu::MipLayout::Pairs);
    EXPECT_EQ(data.gpu_chains[1].first, texture.z);
    EXPECT_EQ(data.gpu_chains[1].layout, gpu::MipLayout::Texels);
    const std::span<gpu::vec4> level0 = gpu::level_texels(data, texture.x);
    auto pair = [&](int x, int y) {
      const std::array<double, 3> moments = precompute::scalar_moment_texel(*m.texture, x, y);
      return glm::vec2(glm::dvec2(moments[0], moments[1] + moments[2]));
    };
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x)
        ASSERT_EQ(level0[static_cast<std::size_t>(y) * s.width + x], gpu::vec4(pair(x, y), pair((x + 1) % s.width, y)))
            << s.width << "x" << s.height << " texel (" << x << ", " << y << ")";
  }
}

}  // namespace texel_plan_test
}  // namespace facet
