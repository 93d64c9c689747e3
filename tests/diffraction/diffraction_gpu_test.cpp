// The float GPU shader (shaders/eval_diffraction.comp) against the double CPU kernel and the exact
// transform, on the same (float-rounded) inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "diffraction/exact_transform.hpp"
#include "diffraction_cases.hpp"
#include "gpu/diffraction_eval.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

using diffraction::DiffractionQuery;
using test::direction;

constexpr double kEpsF = std::numeric_limits<float>::epsilon();

DiffractionQuery rounded_to_float(const DiffractionQuery& q) {
  return {glm::dvec3(glm::vec3(q.wi)), glm::dvec3(glm::vec3(q.wr)), double(float(q.lambda_nm))};
}

std::vector<DiffractionQuery> random_queries(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-0.7, 0.7), lambda(380.0, 780.0);
  std::vector<DiffractionQuery> qs;
  for (int i = 0; i < count; ++i)
    qs.push_back(rounded_to_float({direction(uni(rng), uni(rng)), direction(uni(rng), uni(rng)), lambda(rng)}));
  return qs;
}

// Float error model of one evaluation, in units of |S| (the windowed transform, |S| <= W):
//  - the Taylor sum adds terms up to x^n/n! |H_n| in size: rounding ~ eps sum_n x^n/n! <= eps e^|x|
//    (docs/errata.md#float-taylor-cancellation), and the float tables add the same relative rounding to every term;
//  - k u is rounded (relative eps), which moves the window argument d = sigma |k u - alpha_j| by
//    sigma k |u| eps and the weight exp(-d^2/2) by at most max_d(d e^{-d^2/2}) sigma k |u| eps < sigma k |u| eps.
// Both are multiplied by 2 for the few roundings per step and by W for the bins.
double float_error_bound(const diffraction::SpectralTables& t, const DiffractionQuery& q) {
  const double k = 2 * test::kPi / q.lambda_nm;
  const double x = k * (q.wi.z + q.wr.z) * t.hs_nm;
  const double u = glm::length(glm::dvec2(q.wi + q.wr));
  return 2 * kEpsF * test::window_weight_bound(t) * (std::exp(x) + t.sigma_nm * k * u + 1);
}

TEST(DiffractionGpu, FloatShaderMatchesDoubleKernel) {
  auto context = test::make_validated_context();
  for (
      const char* json :
      {R"({"type":"sinusoid","period_nm":1300,"amplitude_nm":80,"size_um":26,"samples":320})",
       R"({"type":"fingers","period_nm":800,"amplitude_nm":90,"size_um":8,"samples":128,"finger_length_nm":2000,"coherence_um":3})",
       R"({"type":"crossed","period_nm":[1000,1500],"amplitude_nm":100,"size_um":12,"samples":192})"}) {
    const auto g = test::grating(json);
    const auto t = diffraction::build_spectral_tables(g);
    const auto qs = random_queries(3000, 5);
    const auto gpu = facet::gpu::evaluate_diffraction(*context, t, qs);
    ASSERT_EQ(gpu.size(), qs.size());
    double worst_ratio = 0.0;
    for (size_t i = 0; i < qs.size(); ++i) {
      const auto cpu = diffraction::evaluate_taylor(t, qs[i]);
      const double error =
          std::abs(test::field_magnitude(gpu[i].P2, t.sigma_nm) - test::field_magnitude(cpu.P2, t.sigma_nm));
      worst_ratio = std::max(worst_ratio, error / float_error_bound(t, qs[i]));
      // The BRDF is P2 times a smooth factor: relative to the CPU's, within the P2 error plus 1e-5.
      const double allowed =
          2 * float_error_bound(t, qs[i]) / std::max(test::field_magnitude(cpu.P2, t.sigma_nm), 1e-30) + 1e-5;
      if (cpu.P2 > 1e-6 * 4 * test::kPi * t.sigma_nm * t.sigma_nm) {
        EXPECT_NEAR(gpu[i].brdf / cpu.brdf, 1.0, allowed) << json << " query " << i;
      }
    }
    EXPECT_LE(worst_ratio, 1.0) << json;
    std::printf("[ measured ] %s: worst |S| error / float bound = %.3g\n", json, worst_ratio);
  }
}

// docs/errata.md#float-taylor-cancellation: with k w h_s up to 4 pi, float Taylor sums cancel terms ~ x^n / n! up to
// ~2e4. The GPU must stay within the float bound above against the exact transform (plus the tables' Lagrange
// tolerance), and the double CPU twin within the tolerance alone.
TEST(DiffractionGpu, TallGratingUpToFourPiInFloat) {
  auto context = test::make_validated_context();
  // h_s = 250 nm, lambda = 250 nm: x_max = k * 2 * h_s = 4 pi.
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":250,"size_um":8,"samples":128})");
  const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 250.0, .lambda_max_nm = 250.0});
  ASSERT_NEAR(t.x_max, 4 * test::kPi, 1e-9);
  const diffraction::ExactTransform exact(g, t);
  std::vector<DiffractionQuery> qs;
  for (int m = -6; m <= 6; ++m)
    for (double s : {0.0, 0.3, 0.8}) {
      const glm::dvec3 wi = direction(0.1 * s, 0.0);
      const double x_r = -wi.x - m * 250.0 / 1000.0;
      if (std::abs(x_r) < 0.99) qs.push_back(rounded_to_float({wi, direction(x_r, 0.0), 250.0}));
    }
  qs.push_back(rounded_to_float({direction(0, 0), direction(0, 0), 250.0}));  // x = 4 pi exactly
  const auto gpu = facet::gpu::evaluate_diffraction(*context, t, qs);
  double worst_gpu = 0.0, worst_cpu = 0.0;
  for (size_t i = 0; i < qs.size(); ++i) {
    const double e = test::field_magnitude(exact.evaluate(qs[i]).P2, t.sigma_nm);
    const double c = test::field_magnitude(diffraction::evaluate_taylor(t, qs[i]).P2, t.sigma_nm);
    const double gg = test::field_magnitude(gpu[i].P2, t.sigma_nm);
    EXPECT_LE(std::abs(c - e), test::window_weight_bound(t) * 1e-4) << i;
    EXPECT_LE(std::abs(gg - e), float_error_bound(t, qs[i]) + test::window_weight_bound(t) * 1e-4) << i;
    worst_gpu = std::max(worst_gpu, std::abs(gg - e));
    worst_cpu = std::max(worst_cpu, std::abs(c - e));
  }
  std::printf("[ measured ] x = 4 pi: worst |S| error GPU float %.3g, CPU double %.3g (|S| <= 1)\n", worst_gpu,
              worst_cpu);
}

// Finite, non-negative values over the whole domain, grazing directions (z = 0) included.
TEST(DiffractionGpu, FiniteOnTheWholeDomain) {
  auto context = test::make_validated_context();
  const auto g =
      test::grating(R"({"type":"rectangular","period_nm":700,"amplitude_nm":150,"size_um":7,"samples":140})");
  const auto t = diffraction::build_spectral_tables(g);
  std::vector<DiffractionQuery> qs;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 16; ++j)
      for (int k = 0; k <= 8; ++k) {
        const double ti = test::kPi / 2 * i / 8, tr = test::kPi / 2 * k / 8, phi = 2 * test::kPi * j / 16;
        qs.push_back({{std::sin(ti), 0.0, i == 8 ? 0.0 : std::cos(ti)},
                      {std::sin(tr) * std::cos(phi), std::sin(tr) * std::sin(phi), k == 8 ? 0.0 : std::cos(tr)},
                      j % 2 ? 380.0 : 780.0});
      }
  for (const auto& r : gpu::evaluate_diffraction(*context, t, qs)) {
    ASSERT_TRUE(std::isfinite(r.brdf) && r.brdf >= 0.0);
    ASSERT_TRUE(std::isfinite(r.P2) && r.P2 >= 0.0);
  }
}

}  // namespace
}  // namespace facet
