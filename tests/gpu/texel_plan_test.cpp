// The scene upload reserves its texels ahead (gpu/scene_upload.cpp): what it plans for each material
// (microsurface_texels, colormap_texture_texels) must be what the material then appends, for square,
// odd and thin fields, and after other materials' texels.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "gpu/microsurface_upload.hpp"
#include "gpu/texture_upload.hpp"
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

}  // namespace texel_plan_test
}  // namespace facet
