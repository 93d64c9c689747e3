// The data the GPU tracer reads for a height field (renderer/gpu/microsurface_upload.cpp,
// render/heightfield_trace.glsl): where the min-max chain's levels lie (where the tracer computes each
// level to be, without overlaps), that its bounds hold every cell under each node, and that the corner
// quads hold each cell's four vertex heights. Brute force over small fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>

#include "gpu/microsurface_upload.hpp"
#include "layout/heightfield_layout.glsl"
#include "scene/colormap.hpp"

namespace facet {
namespace {

struct Chains {
  gpu::TextureData data;
  gpu::GpuMaterial material;
  int width, height;
  float vertex(int i, int j) const {  // wrapped
    const gpu::uvec4 info = data.levels[material.texture.x].info;
    i = ((i % width) + width) % width;
    j = ((j % height) + height) % height;
    return data.texels[info.x + static_cast<size_t>(j) * width + i].x;
  }
  gpu::uvec4 level(uint32_t record) const { return data.levels[record].info; }
  float texel(uint32_t record, int i, int j, int c) const {
    const gpu::uvec4 info = level(record);
    return data.texels[info.x + static_cast<size_t>(j) * info.y + i][c];
  }
  uint32_t count() const { return material.kind.w; }
  uint32_t bounds(uint32_t l) const { return material.kind.z + l; }
  uint32_t quads() const { return material.kind.z + count(); }  // heightfield_quads
};

Chains chains(int width, int height, unsigned seed) {
  auto field = std::make_shared<assets::ScalarField>();
  field->width = width;
  field->height = height;
  std::mt19937_64 rng(seed);
  // Low noise with rare tall spikes: a node's bound must reach its one spiked cell.
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < width * height; ++k) field->values.push_back(0.01 * u(rng) + (u(rng) < 0.02 ? 1.0 : 0.0));
  MicrosurfaceMaterial m;
  m.heights = field;
  m.texel_size = 0.01;
  m.height_scale = 0.05;
  m.height_colormap = builtin_colormap("viridis");
  Chains c{{}, {}, width, height};
  c.material = gpu::add_microsurface(c.data, m);
  return c;
}

TEST(HeightFieldChains, CornerQuadsHoldEachCellsFourCorners) {
  const Chains c = chains(45, 38, 9);
  const gpu::uvec4 quads = c.level(c.quads());
  ASSERT_EQ(quads.y, 45u);
  ASSERT_EQ(quads.z, 38u);
  for (int j = 0; j < 38; ++j)
    for (int i = 0; i < 45; ++i)
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(c.texel(c.quads(), i, j, k), c.vertex(i + (k & 1), j + (k >> 1))) << "cell " << i << "," << j;
}

// Node (i, j) of level l covers cells [i 2^l, (i + 1) 2^l) x [j 2^l, (j + 1) 2^l) (cut at the field's
// edge); its bound is the extremes of their corners, exactly (the tracer culls by it).
TEST(HeightFieldChains, BoundsAreTheExtremesOfTheCellsUnderEachNode) {
  const Chains c = chains(45, 38, 5);
  for (uint32_t l = 0; l < c.count(); ++l) {
    const gpu::uvec4 info = c.level(c.bounds(l));
    const int node = 1 << l;
    for (int j = 0; j < static_cast<int>(info.z); ++j)
      for (int i = 0; i < static_cast<int>(info.y); ++i) {
        float lo = 1e30f, hi = -1e30f;
        for (int y = j * node; y < std::min((j + 1) * node, 38); ++y)
          for (int x = i * node; x < std::min((i + 1) * node, 45); ++x)
            for (int k = 0; k < 4; ++k) {
              lo = std::min(lo, c.vertex(x + (k & 1), y + (k >> 1)));
              hi = std::max(hi, c.vertex(x + (k & 1), y + (k >> 1)));
            }
        EXPECT_EQ(c.texel(c.bounds(l), i, j, 0), lo) << "level " << l << " node " << i << "," << j;
        EXPECT_EQ(c.texel(c.bounds(l), i, j, 1), hi) << "level " << l << " node " << i << "," << j;
      }
  }
}

// The tracer finds level l of the bounds at FACET_HEIGHTFIELD_BOUND_LEVEL(span, l) after level 0, span
// = twice the distance from level 0 to level 1, with ceil(size / 2^l) nodes a row
// (render/heightfield_trace.glsl): the records say the same, and no level overlaps another or leaves its
// chain, on odd, one-texel-wide and non-square fields; the corner quads follow the chain.
TEST(HeightFieldChains, BoundLevelsLieWhereTheTracerComputesThem) {
  const int sizes[][2] = {{1, 1}, {1, 7}, {3, 1}, {5, 3}, {8, 8}, {17, 4}, {33, 64}, {45, 38}};
  for (const auto& size : sizes) {
    const Chains c = chains(size[0], size[1], 7);
    const uint32_t span = gpu::heightfield_bound_span(c.width, c.height);
    const uint64_t base = c.level(c.bounds(0)).x;
    if (c.count() > 1) {
      EXPECT_EQ(2 * (c.level(c.bounds(1)).x - base), span) << c.width << "x" << c.height;
    }
    uint64_t end = base;  // past the last texel of the levels so far
    for (uint32_t l = 0; l < c.count(); ++l) {
      const gpu::uvec4 info = c.level(c.bounds(l));
      EXPECT_EQ(info.x, base + FACET_HEIGHTFIELD_BOUND_LEVEL(span, l)) << c.width << "x" << c.height << " level " << l;
      EXPECT_EQ(info.y, (static_cast<uint32_t>(c.width) + (1u << l) - 1) >> l);
      EXPECT_EQ(info.z, (static_cast<uint32_t>(c.height) + (1u << l) - 1) >> l);
      EXPECT_GE(info.x, end) << c.width << "x" << c.height << " level " << l;
      end = info.x + static_cast<uint64_t>(info.y) * info.z;
    }
    EXPECT_LE(end, base + span) << c.width << "x" << c.height;
    EXPECT_GE(c.level(c.quads()).x, base + span) << c.width << "x" << c.height;
  }
}

}  // namespace
}  // namespace facet
