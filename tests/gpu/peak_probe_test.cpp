// The host-peak probe (renderer/gpu/peak_probe.hpp): every invocation runs the FMAs the rate assumes,
// counted by the shader itself (chains of x = fma(x, 1, 1) from 0 end at their length), and the
// measured rates are finite and positive.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "gpu/peak_probe.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace peak_probe_test {

// Lengths up to lavapipe's loop limit (65 535 iterations): a limit hit would leave short chains.
TEST(PeakProbe, EveryInvocationRunsTheFmasTheRateAssumes) {
  auto context = test::make_validated_context();
  for (std::uint32_t iterations : {1u, 128u, 65535u}) {
    const gpu::ProbeShape shape{.workgroups = 8, .iterations = iterations, .dispatches = 1};
    const std::vector<float> counts = gpu::count_probe_fmas(*context, shape);
    ASSERT_EQ(counts.size(), 8u * 64u);
    // 4 chains of 4 lanes, one fma per lane and iteration: the count written down in the shader.
    const double per_invocation = 4.0 * 4.0 * iterations;
    for (float count : counts) ASSERT_EQ(count, per_invocation) << iterations;
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), 0.0), gpu::probe_fmas(shape));
    EXPECT_EQ(gpu::probe_texel_reads(shape), 8.0 * 64.0 * iterations * 4.0);
  }
}

TEST(PeakProbe, RatesAreFiniteAndPositive) {
  auto context = test::make_validated_context();
  const gpu::PeakProbe peak = gpu::probe_peak(*context, {.workgroups = 256, .iterations = 64, .dispatches = 2});
  EXPECT_TRUE(std::isfinite(peak.fma_per_second));
  EXPECT_GT(peak.fma_per_second, 0.0);
  EXPECT_TRUE(std::isfinite(peak.texel_reads_per_second));
  EXPECT_GT(peak.texel_reads_per_second, 0.0);
}

TEST(PeakProbe, RefusesShapesTheDeviceCannotRun) {
  auto context = test::make_validated_context();
  EXPECT_THROW(gpu::probe_peak(*context, {.workgroups = 0}), Error);
  EXPECT_THROW(gpu::probe_peak(*context, {.iterations = 0}), Error);
  EXPECT_THROW(gpu::probe_peak(*context, {.iterations = 65536}), Error);
  EXPECT_THROW(gpu::probe_peak(*context, {.dispatches = 0}), Error);
}

}  // namespace peak_probe_test
}  // namespace facet
