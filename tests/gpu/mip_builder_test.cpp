// MIP chains built on the GPU (shaders/build_mips.comp through gpu::append_mip_chain and
// gpu::build_gpu_mips, as the scene upload builds its moment maps) against the CPU reference
// precompute::build_moment_mips: power-of-two, odd and 1 x N sizes, several chains in one buffer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "gpu/mip_builder.hpp"
#include "gpu/texture_upload.hpp"
#include "precompute/moment_mips.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

struct Size {
  int width, height;
};

TEST(MipBuilder, ChainSizesHalveRoundingUpDownToOneTexel) {
  const std::vector<glm::uvec2> sizes = gpu::mip_chain_sizes(13, 4);
  const std::vector<glm::uvec2> expected = {{13, 4}, {7, 2}, {4, 1}, {2, 1}, {1, 1}};
  EXPECT_EQ(sizes, expected);
  EXPECT_EQ(gpu::mip_chain_sizes(1, 1).size(), 1u);
}

// Every level of every chain equals the double CPU chain. Float tolerance: each level is a weighted
// mean of at most 4 children (weights exact integers), so its relative rounding grows by at most
// ~4 eps_f per level (a sum of 4 terms, one division); |values| <= 1, so |gpu - cpu| <= 4 eps_f (l + 1) + eps_f.
// Beside each chain of texels, a chain of pairs of its first two channels (MipLayout::Pairs) holds in
// every texel (x, y) the chain of texels' (x, y) and ((x + 1) mod width, y), bit for bit: the same sums in
// the same order.
TEST(MipBuilder, GpuChainsEqualTheCpuChains) {
  auto context = test::make_validated_context();
  const Size sizes[] = {{64, 64}, {13, 7}, {1, 5}, {5, 1}, {1, 1}, {3, 40}, {37, 23}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  gpu::TextureData data;
  std::vector<precompute::MomentMips> cpu;
  std::vector<gpu::uint> firsts, pair_firsts;
  for (const Size s : sizes) {
    std::vector<double> level0(static_cast<size_t>(s.width) * s.height * 4);
    for (double& v : level0) v = unit(rng);
    std::vector<gpu::vec4> texels(level0.size() / 4);
    for (size_t i = 0; i < texels.size(); ++i)
      texels[i] = gpu::vec4(level0[4 * i], level0[4 * i + 1], level0[4 * i + 2], level0[4 * i + 3]);
    firsts.push_back(gpu::append_mip_chain(data, s.width, s.height));
    std::ranges::copy(texels, gpu::level_texels(data, firsts.back()).begin());
    pair_firsts.push_back(gpu::append_mip_chain(data, s.width, s.height, gpu::MipLayout::Pairs));
    const std::span<gpu::vec4> pairs = gpu::level_texels(data, pair_firsts.back());
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        const size_t row = static_cast<size_t>(y) * s.width;
        pairs[row + x] = gpu::vec4(glm::vec2(texels[row + x]), glm::vec2(texels[row + (x + 1) % s.width]));
      }
    cpu.push_back(precompute::build_moment_mips(s.width, s.height, 4, std::move(level0)));
  }
  vk::Buffer buffer = vk::Buffer::from(*context, std::span<const gpu::vec4>(data.texels));
  gpu::build_gpu_mips(*context, buffer, data);
  std::vector<gpu::vec4> result(data.texels.size());
  buffer.download(result.data(), result.size() * sizeof(gpu::vec4));

  const double eps_f = std::ldexp(1.0, -24);
  double worst_ratio = 0.0;
  for (size_t c = 0; c < cpu.size(); ++c) {
    ASSERT_EQ(data.gpu_chains[2 * c].levels, cpu[c].levels.size());
    ASSERT_EQ(data.gpu_chains[2 * c + 1].layout, gpu::MipLayout::Pairs);
    for (size_t l = 0; l < cpu[c].levels.size(); ++l) {
      const gpu::GpuTextureLevel& level = data.levels[firsts[c] + l];
      ASSERT_EQ(level.info.y, static_cast<gpu::uint>(cpu[c].levels[l].width));
      ASSERT_EQ(level.info.z, static_cast<gpu::uint>(cpu[c].levels[l].height));
      const double tolerance = 4 * eps_f * static_cast<double>(l + 1) + eps_f;
      for (int y = 0; y < cpu[c].levels[l].height; ++y)
        for (int x = 0; x < cpu[c].levels[l].width; ++x) {
          const double* want = cpu[c].texel(static_cast<int>(l), x, y);
          const gpu::vec4 got = result[level.info.x + static_cast<size_t>(y) * level.info.y + x];
          for (int k = 0; k < 4; ++k) {
            const double error = std::abs(got[k] - want[k]);
            worst_ratio = std::max(worst_ratio, error / tolerance);
            ASSERT_LE(error, tolerance) << sizes[c].width << "x" << sizes[c].height << " level " << l << " (" << x
                                        << ", " << y << ") channel " << k;
          }
          const size_t row = static_cast<size_t>(y) * level.info.y;
          const gpu::vec4 next = result[level.info.x + row + (x + 1) % level.info.y];
          const gpu::vec4 pair = result[data.levels[pair_firsts[c] + l].info.x + row + x];
          ASSERT_EQ(pair, gpu::vec4(got.x, got.y, next.x, next.y))
              << sizes[c].width << "x" << sizes[c].height << " level " << l << " (" << x << ", " << y << ")";
        }
    }
  }
  std::printf("worst |gpu - cpu| / tolerance: %.3f\n", worst_ratio);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// A chain larger than a storage buffer may be (maxStorageBufferRange, 128 MiB on lavapipe): a 2560²
// level 0 (140 MB with its levels). Level 0 holds (x, y, x + y, 1) / 2560 at texel (x, y), so a texel
// of level l covering level-0 columns [x0, x1) and rows [y0, y1) is the plain mean
// ((x0 + x1 - 1) / 2, (y0 + y1 - 1) / 2, their sum, 2560) / 2560: a closed form for every level.
TEST(MipBuilder, ChainsBeyondTheStorageBufferRangeBuild) {
  auto context = test::make_validated_context();
  constexpr int kSide = 2560;
  std::vector<gpu::vec4> level0(static_cast<size_t>(kSide) * kSide);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      level0[static_cast<size_t>(y) * kSide + x] = gpu::vec4(x, y, x + y, kSide) / float(kSide);
  gpu::TextureData data;
  const gpu::uint first = gpu::append_mip_chain(data, kSide, kSide);
  std::ranges::copy(level0, gpu::level_texels(data, first).begin());
  level0 = {};
  vk::Buffer buffer = vk::Buffer::from(*context, std::span<const gpu::vec4>(data.texels));
  ASSERT_GT(buffer.size(), context->limits().maxStorageBufferRange);
  gpu::build_gpu_mips(*context, buffer, data);
  std::vector<gpu::vec4> result(data.texels.size());
  buffer.download(result.data(), result.size() * sizeof(gpu::vec4));

  const double eps_f = std::ldexp(1.0, -24);
  for (gpu::uint l = 1; l < data.gpu_chains[0].levels; ++l) {
    const gpu::GpuTextureLevel& level = data.levels[first + l];
    const int span = 1 << l;
    const double tolerance = 4 * eps_f * static_cast<double>(l + 1) + eps_f;
    for (gpu::uint y = 0; y < level.info.z; ++y)
      for (gpu::uint x = 0; x < level.info.y; ++x) {
        const double mean_x = (x * span + std::min<double>((x + 1.0) * span, kSide) - 1.0) / 2.0 / kSide;
        const double mean_y = (y * span + std::min<double>((y + 1.0) * span, kSide) - 1.0) / 2.0 / kSide;
        const gpu::vec4 got = result[level.info.x + static_cast<size_t>(y) * level.info.y + x];
        ASSERT_NEAR(got.x, mean_x, tolerance) << "level " << l << " (" << x << ", " << y << ")";
        ASSERT_NEAR(got.y, mean_y, tolerance) << "level " << l << " (" << x << ", " << y << ")";
        ASSERT_NEAR(got.z, mean_x + mean_y, 2 * tolerance) << "level " << l << " (" << x << ", " << y << ")";
        ASSERT_NEAR(got.w, 1.0, tolerance) << "level " << l << " (" << x << ", " << y << ")";
      }
  }
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace
}  // namespace facet
