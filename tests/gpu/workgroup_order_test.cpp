// The workgroup permutation of the render pass (renderer/gpu/workgroup_order.hpp): a bijection for
// every tile size, and it spreads each lavapipe thread's contiguous share of the workgroups over
// the whole tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "common/error.hpp"
#include "gpu/workgroup_order.hpp"

namespace facet {
namespace {

TEST(WorkgroupOrder, StrideIsCoprimeSoEveryBlockIsRenderedOnce) {
  for (std::uint32_t n = 1; n <= 5000; ++n) {
    const std::uint32_t s = gpu::workgroup_spread_stride(n);
    ASSERT_LT(s, std::max(n, 2u)) << n;
    ASSERT_EQ(std::gcd(s, n), 1u) << n;
  }
  for (std::uint32_t n : {1u, 2u, 16u, 1024u, 1023u, 4096u, gpu::kMaxTileBlocks}) {
    const std::uint32_t s = gpu::workgroup_spread_stride(n);
    std::vector<bool> seen(n, false);
    for (std::uint32_t g = 0; g < n; ++g) seen[(g * s) % n] = true;  // the shader's arithmetic, in 32 bits
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), static_cast<long>(n)) << n;
  }
  EXPECT_THROW(gpu::workgroup_spread_stride(0), Error);
  EXPECT_THROW(gpu::workgroup_spread_stride(gpu::kMaxTileBlocks + 1), Error);
}

// Lavapipe's T threads take the workgroups in T contiguous runs. A costly band of 4 block rows
// (32 pixel rows: a highlight, a band of diffraction orders) must be shared about evenly: each
// run holds within 20 % of 1/T of the band's blocks (row-major order without the permutation:
// one run holds all of it, 100 % off).
TEST(WorkgroupOrder, EachThreadsRunCoversEveryBandOfTheTile) {
  for (const auto& [gx, gy] : {std::pair{32u, 32u}, {64u, 64u}, {32u, 16u}, {30u, 30u}}) {
    const std::uint32_t n = gx * gy, s = gpu::workgroup_spread_stride(n);
    for (std::uint32_t threads : {2u, 4u}) {
      for (std::uint32_t band = 0; band < gy; band += 4) {
        std::vector<double> share(threads, 0.0);
        for (std::uint32_t t = 0; t < threads; ++t)
          for (std::uint32_t g = t * n / threads; g < (t + 1) * n / threads; ++g) {
            const std::uint32_t row = (g * s) % n / gx;
            share[t] += row >= band && row < band + 4;
          }
        const double even = std::accumulate(share.begin(), share.end(), 0.0) / threads;
        for (double x : share) EXPECT_LE(std::abs(x - even), 0.2 * even) << gx << "x" << gy << " T " << threads;
      }
    }
  }
}

}  // namespace
}  // namespace facet
