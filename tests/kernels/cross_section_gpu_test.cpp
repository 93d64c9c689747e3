// The GPU's fast cross-sections (shaders/eval_cross_section.comp, float) against the CPU exact
// evaluation in double, over the whole parameter domain of every distribution.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "eval_cross_section.spv.h"
#include "gpu/batch_eval.hpp"
#include "kernels/cross_section_exact.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

// The target for the fast path (absolute, or relative to sigma where sigma > 1).
constexpr double kTolerance = 1e-4;

TEST(CrossSectionGpu, FastKernelsMatchExactOverTheDomain) {
  struct Query {
    int ndf;
    double param, u;
  };
  std::vector<Query> queries;
  for (int ndf = 0; ndf < 4; ++ndf)
    for (int i = 0; i <= 60; ++i) {
      // alpha in [1e-3, 1e3] log-spaced; b of Kagiwada-Kalaba in [1e-6, 1 - 1e-6].
      double param = ndf == 2 ? (i == 0 ? 1e-6 : i == 60 ? 1 - 1e-6 : i / 60.0) : std::pow(10.0, -3 + 6 * i / 60.0);
      for (int j = 0; j <= 100; ++j) queries.push_back({ndf, param, -1.0 + 2.0 * j / 100});
    }
  std::vector<gpu::EvalRecord> records;
  for (const auto& q : queries) records.push_back({glm::vec4(q.ndf, q.param, q.u, 0), glm::vec4(0)});
  auto context = test::make_validated_context();
  auto results = gpu::run_batch_eval(*context, "eval_cross_section", eval_cross_section_spv, records);

  double worst[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    // The GPU sees the float-rounded inputs; so does the exact reference here.
    const double param = static_cast<float>(q.param), u = static_cast<float>(q.u);
    const double exact = kernels::cross_section(q.ndf, param, u, /*exact=*/true);
    const double gpu = results[i].a.x;
    ASSERT_TRUE(std::isfinite(gpu) && gpu >= 0.0) << q.ndf << " " << param << " " << u;
    const double error = std::abs(gpu - exact) / std::max(1.0, exact);
    worst[q.ndf] = std::max(worst[q.ndf], error);
    EXPECT_LE(error, kTolerance) << "ndf " << q.ndf << " param " << param << " u " << u << ": gpu " << gpu << " exact "
                                 << exact;
  }
  std::printf("GPU fast vs exact, worst |error|/max(1, sigma): beckmann %.2g ggx %.2g kk %.2g sg %.2g\n", worst[0],
              worst[1], worst[2], worst[3]);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace
}  // namespace facet
