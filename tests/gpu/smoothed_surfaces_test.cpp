// The data behind the smoothed surfaces `filtered` traces (T2, docs/microsurface_filtering.md;
// renderer/gpu/microsurface_upload.cpp): corner heights are the field's area means around each corner,
// and the dilated min-max bounds of every node hold every smoothed surface the traversal can meet
// under it, so no node that a smoothed surface crosses is culled. Brute force over small fields.
// Also where the min-max chains lie: where the tracer computes each level to be, without overlaps.
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
  uint32_t dilated(uint32_t l) const { return material.kind.z + count() + l; }
  uint32_t corners(uint32_t l) const { return material.kind.z + 2 * count() + l - 1; }  // l >= 1
  uint32_t quads(uint32_t l) const { return material.kind.z + 3 * count() + l - 1; }
};

Chains chains(int width, int height, unsigned seed) {
  auto field = std::make_shared<assets::ScalarField>();
  field->width = width;
  field->height = height;
  std::mt19937_64 rng(seed);
  // Low noise with rare tall spikes: the averages around a node then reach heights its own cells lack.
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

// Mean over cells [x0, x1) x [y0, y1) (wrapped) of each cell's mean height (the mean of its corners).
double area_mean(const Chains& c, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i)
      sum += 0.25 * (c.vertex(i, j) + c.vertex(i + 1, j) + c.vertex(i, j + 1) + c.vertex(i + 1, j + 1));
  return sum / ((x1 - x0) * (y1 - y0));
}

TEST(SmoothedSurfaces, CornerHeightsAreAreaMeansAroundTheCorner) {
  const Chains c = chains(32, 16, 3);
  for (uint32_t l = 1; l < c.count(); ++l) {
    const gpu::uvec4 info = c.level(c.corners(l));
    const int node = 1 << l;
    for (int j = 0; j < static_cast<int>(info.z); ++j)
      for (int i = 0; i < static_cast<int>(info.y); ++i) {
        // Power-of-two sizes: the four nodes around corner (i, j) are full 2^l squares, except where
        // the level has a single node along an axis (then the "four" are the same node twice).
        const int wx = static_cast<int>(info.y) == 1 ? 1 : 2, wy = static_cast<int>(info.z) == 1 ? 1 : 2;
        const int x0 = (i - (wx - 1)) * node, y0 = (j - (wy - 1)) * node;
        const double expected = area_mean(c, x0, x0 + wx * node, y0, y0 + wy * node);
        EXPECT_NEAR(c.texel(c.corners(l), i, j, 0), expected, 1e-6) << "level " << l << " corner " << i << "," << j;
      }
  }
}

// For every node of every level K (a non-power-of-two field, so tiles end in cut nodes): the corner
// heights of every smoothed level L <= K (the vertices for L = 0) on the node's closed extent lie in
// its dilated bounds; the surfaces are bilinear between those corners, so they lie in them too.
TEST(SmoothedSurfaces, DilatedBoundsHoldEverySmoothedSurface) {
  const Chains c = chains(45, 38, 5);
  int checked = 0;
  for (uint32_t k = 0; k < c.count(); ++k) {
    const gpu::uvec4 info = c.level(c.dilated(k));
    for (int j = 0; j < static_cast<int>(info.z); ++j)
      for (int i = 0; i < static_cast<int>(info.y); ++i) {
        const float lo = c.texel(c.dilated(k), i, j, 0), hi = c.texel(c.dilated(k), i, j, 1);
        const int x0 = i << k, x1 = std::min((i + 1) << k, c.width), y0 = j << k, y1 = std::min((j + 1) << k, c.height);
        for (uint32_t l = 0; l <= k; ++l) {
          const gpu::uvec4 corners = l == 0 ? c.level(c.material.texture.x) : c.level(c.corners(l));
          // Corners of level l at x = a 2^l (a <= nodes; the last is the tile's end, i.e. corner 0).
          for (int b = 0; b <= static_cast<int>(corners.z); ++b)
            for (int a = 0; a <= static_cast<int>(corners.y); ++a) {
              const int x = std::min(a << l, c.width), y = std::min(b << l, c.height);
              if (x < x0 || x > x1 || y < y0 || y > y1) continue;
              const int ca = a == static_cast<int>(corners.y) ? 0 : a, cb = b == static_cast<int>(corners.z) ? 0 : b;
              const float z = l == 0 ? c.vertex(ca, cb) : c.texel(c.corners(l), ca, cb, 0);
              EXPECT_GE(z, lo) << "K " << k << " node " << i << "," << j << " L " << l;
              EXPECT_LE(z, hi) << "K " << k << " node " << i << "," << j << " L " << l;
              ++checked;
            }
        }
      }
  }
  EXPECT_GT(checked, 5000);
}

// A node's corner quad holds the four corners the tracer's bilinear patch over it uses: vertices
// (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1) of its level's corner grid (level 0: the field's
// vertices), wrapped, on a non-power-of-two field whose coarse levels wrap at cut nodes.
TEST(SmoothedSurfaces, CornerQuadsHoldEachNodesFourCorners) {
  const Chains c = chains(45, 38, 9);
  int checked = 0;
  for (uint32_t l = 0; l < c.count(); ++l) {
    const uint32_t grid = l == 0 ? c.material.texture.x : c.corners(l);
    const gpu::uvec4 info = c.level(grid), quads = c.level(c.quads(l));
    ASSERT_EQ(quads.y, info.y);
    ASSERT_EQ(quads.z, info.z);
    const int w = static_cast<int>(info.y), h = static_cast<int>(info.z);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        for (int k = 0; k < 4; ++k) {
          const int a = (i + (k & 1)) % w, b = (j + (k >> 1)) % h;
          EXPECT_EQ(c.texel(c.quads(l), i, j, k), c.texel(grid, a, b, 0)) << "level " << l << " node " << i << "," << j;
          ++checked;
        }
  }
  EXPECT_GT(checked, 4 * 45 * 38);
}

// The tracer finds level l of the bounds it tests at FACET_HEIGHTFIELD_BOUND_LEVEL(span, l) after
// level 0, span = dilated level 0 - bounds level 0, with ceil(size / 2^l) nodes a row
// (render/heightfield_trace.glsl): the records say the same, and no level overlaps another or leaves
// its chain, on odd, one-texel-wide and non-square fields.
TEST(SmoothedSurfaces, BoundLevelsLieWhereTheTracerComputesThem) {
  const int sizes[][2] = {{1, 1}, {1, 7}, {3, 1}, {5, 3}, {8, 8}, {17, 4}, {33, 64}, {45, 38}};
  for (const auto& size : sizes) {
    const Chains c = chains(size[0], size[1], 7);
    const uint32_t span = gpu::heightfield_bound_span(c.width, c.height);
    const uint32_t bounds0 = c.level(c.material.kind.z).x, dilated0 = c.level(c.dilated(0)).x;
    EXPECT_EQ(dilated0 - bounds0, span) << c.width << "x" << c.height;
    for (const uint32_t first : {c.material.kind.z, c.dilated(0)}) {
      const uint64_t base = c.level(first).x;
      uint64_t end = base;  // past the last texel of the levels so far
      for (uint32_t l = 0; l < c.count(); ++l) {
        const gpu::uvec4 info = c.level(first + l);
        EXPECT_EQ(info.x, base + FACET_HEIGHTFIELD_BOUND_LEVEL(span, l)) << c.width << "x" << c.height << " level " << l;
        EXPECT_EQ(info.y, (static_cast<uint32_t>(c.width) + (1u << l) - 1) >> l);
        EXPECT_EQ(info.z, (static_cast<uint32_t>(c.height) + (1u << l) - 1) >> l);
        EXPECT_GE(info.x, end) << c.width << "x" << c.height << " level " << l;
        end = info.x + static_cast<uint64_t>(info.y) * info.z;
      }
      EXPECT_LE(end, base + span) << c.width << "x" << c.height;
    }
    if (c.count() > 1) {
      EXPECT_GE(c.level(c.corners(1)).x, dilated0 + span);
    }
  }
}

}  // namespace
}  // namespace facet
