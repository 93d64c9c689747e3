// The lobe averaged over a pixel (normal_density_over_parallelogram, eq. P2 of docs/microsurface_filtering.md;
// microflake_D_over_pixel, eq. F2 of docs/microflake_brdf.md) compiled for the device
// (tests/gpu/shaders/pixel_lobe_probe.comp, microflake_lobe_probe.comp) against the double twins on the same
// inputs: lobes from far wider to far narrower than the pixel, square, sheared and degenerate pixels, the
// lobe's mean inside, on the edges of and beyond the pixel, and extreme inputs (finite, non-negative).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/shared.hpp"
#include "microflake_lobe_probe.spv.h"
#include "pixel_lobe_probe.spv.h"
#include "support/vulkan_fixture.hpp"
#include "vk/kernel.hpp"

namespace facet {
namespace {

namespace k64 = kernels::f64;

struct Probe {
  glm::dvec2 offset, step_x, step_y;  // offset: the pixel's centre less the lobe's mean
  glm::dvec3 cov;
  double det_min;
};

// Runs a probe shader over records of three vec4 each; returns the first component of each record's first.
std::vector<double> run_probe(vk::Context& context, const char* name, std::span<const uint32_t> spirv,
                              std::vector<glm::vec4> records) {
  vk::Buffer buffer = vk::Buffer::from(context, std::span<const glm::vec4>(records));
  vk::Kernel kernel(context, {.name = name, .spirv = spirv, .buffer_count = 1, .specialization = {}});
  const vk::Buffer* bindings[] = {&buffer};
  kernel.dispatch(bindings, nullptr, {static_cast<uint32_t>((records.size() / 3 + 63) / 64), 1, 1});
  buffer.download(records.data(), records.size() * sizeof(glm::vec4));
  std::vector<double> values;
  for (size_t i = 0; i < records.size() / 3; ++i) values.push_back(records[3 * i].x);
  return values;
}

// The largest error of `device` against `expected(i)` over consecutive cases of `per_case` probes, each relative
// to its case's largest expected value (the first `cases * per_case` probes).
template <class Expected>
double worst_relative_error(const std::vector<double>& device, size_t cases, size_t per_case, Expected expected) {
  double worst = 0.0;
  for (size_t c = 0; c < cases; ++c) {
    double peak = 0.0, largest_error = 0.0;
    for (size_t i = c * per_case; i < (c + 1) * per_case; ++i) {
      const double value = expected(i);
      peak = std::max(peak, value);
      largest_error = std::max(largest_error, std::abs(device[i] - value));
    }
    worst = std::max(worst, largest_error / peak);
  }
  return worst;
}

std::vector<double> run_on_device(vk::Context& context, const std::vector<Probe>& probes) {
  std::vector<glm::vec4> records;
  for (const Probe& p : probes) {
    records.emplace_back(p.offset.x, p.offset.y, p.step_x.x, p.step_x.y);
    records.emplace_back(p.step_y.x, p.step_y.y, 0.0f, 0.0f);
    records.emplace_back(p.cov.x, p.cov.y, p.cov.z, p.det_min);
  }
  return run_probe(context, "pixel_lobe_probe", pixel_lobe_probe_spv, std::move(records));
}

// Within 1e-4 of each case's peak density (the float twin on the CPU: 4.3e-6, tests/kernels); extreme
// inputs finite and non-negative.
TEST(PixelLobeGpu, DeviceFollowsTheDoubleTwin) {
  auto context = test::make_validated_context();
  struct Shape {
    glm::dvec3 cov;
    glm::dvec2 step_x, step_y;
  };
  const Shape shapes[] = {
      {{1e-2, 1e-3, 0.0}, {0.02, 0.001}, {0.0, 0.02}},       {{1e-6, 1e-6, 0.0}, {0.02, 0.001}, {0.0, 0.02}},
      {{2e-5, 1e-5, 1.2e-5}, {0.02, 0.001}, {0.012, 0.016}}, {{1e-6, 1e-2, 0.0}, {0.02, 0.0}, {0.0, 0.004}},
      {{1e-4, 1e-4, 0.0}, {0.02, 0.001}, {1e-5, 0.0}},       {{1e-3, 2e-3, 5e-4}, {1e-7, 0.0}, {0.0, 1e-7}}};
  std::vector<Probe> probes;
  for (const Shape& s : shapes)
    for (double a = -1.0; a <= 1.0; a += 0.125)
      for (double b = -1.0; b <= 1.0; b += 0.125)
        probes.push_back({a * s.step_x + b * s.step_y, s.step_x, s.step_y, s.cov, 0.0});
  const size_t regular = probes.size();
  for (glm::dvec3 cov : {glm::dvec3(1e-12, 1e-12, 0.0), glm::dvec3(1e-4, 1e-4, 1e-4), glm::dvec3(1e6, 1e-8, 0.0)})
    for (glm::dvec4 steps : {glm::dvec4(0.0), glm::dvec4(0.01, 0.0, 0.0, 0.0), glm::dvec4(0.01, 0.01, 0.02, 0.02),
                             glm::dvec4(1e3, 0.0, 0.0, 1e3), glm::dvec4(1e-30, 0.0, 0.0, 1e-30)})
      for (glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(0.3, -0.2), glm::dvec2(1e3, 1e3)})
        probes.push_back({offset, {steps.x, steps.y}, {steps.z, steps.w}, cov, 1e-20});
  const std::vector<double> device = run_on_device(*context, probes);
  const double worst = worst_relative_error(device, std::size(shapes), regular / std::size(shapes), [&](size_t i) {
    const Probe& p = probes[i];
    return k64::normal_density_over_parallelogram(p.offset, p.step_x, p.step_y, glm::dvec2(0.0), p.cov, p.det_min);
  });
  std::printf("device vs double: %.2e of the peak\n", worst);
  EXPECT_LT(worst, 1e-4);
  for (size_t i = regular; i < probes.size(); ++i)
    EXPECT_TRUE(std::isfinite(device[i]) && device[i] >= 0.0) << i << ": " << device[i];
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// microflake_D_over_pixel on the device against the double twin: each distribution narrow and moderate,
// pixels from a tenth of the lobe to 30 lobes wide, within 1e-4 of each case's peak (the float twin on the
// CPU: 1.5e-4 of its peak over a wider range, tests/kernels); extreme inputs finite and non-negative.
TEST(PixelLobeGpu, MicroflakeLobeFollowsTheDoubleTwin) {
  auto context = test::make_validated_context();
  struct Case {
    int ndf;
    double param, size;
  };
  std::vector<Case> cases;
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG})
    for (double size : {0.002, 0.03, 0.3}) {
      cases.push_back({ndf, ndf == NDF_KK ? 0.999 : 0.02, size});
      cases.push_back({ndf, ndf == NDF_KK ? 0.9 : 0.3, size});
    }
  const auto direction = [](glm::dvec2 s) { return glm::normalize(glm::dvec3(-s.x, -s.y, 1.0)); };
  std::vector<glm::vec4> records;
  std::vector<std::pair<glm::dvec3, glm::dvec4>> inputs;
  for (const Case& c : cases)
    for (double a = -1.0; a <= 1.0; a += 0.25)
      for (double b = -1.0; b <= 1.0; b += 0.25) {
        const glm::dvec4 steps = c.size * glm::dvec4(1.0, 0.1, 0.4, 0.9);
        inputs.emplace_back(direction(a * glm::dvec2(steps.x, steps.y) + b * glm::dvec2(steps.z, steps.w)), steps);
      }
  const size_t per_case = inputs.size() / cases.size();
  for (size_t i = 0; i < inputs.size(); ++i) {
    const Case& c = cases[i / per_case];
    records.emplace_back(glm::vec3(inputs[i].first), static_cast<float>(c.param));
    records.emplace_back(inputs[i].second);
    records.emplace_back(static_cast<float>(c.ndf), 0.0f, 0.0f, 0.0f);
  }
  const size_t regular = inputs.size();
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG})
    for (double param : {1e-4, ndf == NDF_KK ? 1.0 - 1e-7 : 50.0})
      for (glm::dvec3 h : {glm::dvec3(0.0, 0.0, 1.0), glm::normalize(glm::dvec3(1.0, 0.0, 1e-6))})
        for (glm::dvec4 steps : {glm::dvec4(1e-30, 0.0, 0.0, 1e-30), glm::dvec4(1e3, 0.0, 0.0, 1e3)}) {
          records.emplace_back(glm::vec3(h), static_cast<float>(param));
          records.emplace_back(steps);
          records.emplace_back(static_cast<float>(ndf), 0.0f, 0.0f, 0.0f);
        }
  const std::vector<double> device = run_probe(*context, "microflake_lobe_probe", microflake_lobe_probe_spv, records);
  const double worst = worst_relative_error(device, cases.size(), per_case, [&](size_t i) {
    const Case& c = cases[i / per_case];  // the inputs as the device gets them, in float
    return k64::microflake_D_over_pixel(c.ndf, static_cast<float>(c.param), glm::dvec3(glm::vec3(inputs[i].first)),
                                        glm::dvec4(glm::vec4(inputs[i].second)));
  });
  std::printf("microflake lobe, device vs double: %.2e of the peak\n", worst);
  EXPECT_LT(worst, 1e-4);
  for (size_t i = regular; i < device.size(); ++i)
    EXPECT_TRUE(std::isfinite(device[i]) && device[i] >= 0.0) << i << ": " << device[i];
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace
}  // namespace facet
