#include "gpu/peak_probe.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <string>

#include "common/error.hpp"
#include "gpu/contiguous_ids.hpp"
#include "peak_probe.spv.h"
#include "vk/buffer.hpp"
#include "vk/kernel.hpp"

namespace facet::gpu {

using uint = std::uint32_t;  // as in gpu/scene_layout.hpp: the layout's GLSL type names

namespace {

#include "layout/peak_probe_layout.glsl"
static_assert(sizeof(ProbePush) == 32);
static_assert(contiguous_ids(std::array<int, FACET_PROBE_BINDING_COUNT>{FACET_PROBE_BINDING_OUT, FACET_PROBE_BINDING_TEXELS}));

// 2^12 texels of 16 bytes: 64 KiB, within a core's L2 like the scene records and colour maps the
// render pass reads most, so the figure is the gather's throughput rather than memory latency.
constexpr uint32_t kTexelCount = 1u << 12;
// Lavapipe ends a shader invocation's loops silently after 65 535 iterations (docs: PLATFORM notes).
constexpr uint32_t kMaxIterations = 65535;

class ProbeKernel {
 public:
  ProbeKernel(vk::Context& context, const ProbeShape& shape)
      : shape_(checked(context, shape)),
        out_(context, static_cast<VkDeviceSize>(shape.workgroups) * FACET_PROBE_WORKGROUP * sizeof(float)),
        texels_(vk::Buffer::from(context, std::span<const std::array<uint32_t, 4>>(texel_pattern()))),
        kernel_(context, {.name = "peak_probe",
                          .spirv = peak_probe_spv,
                          .buffer_count = FACET_PROBE_BINDING_COUNT,
                          .push_constant_bytes = sizeof(ProbePush),
                          .specialization = {},
                          .buffer_kinds = {vk::BufferKind::Storage, vk::BufferKind::Texels}}) {
  }

  // Device milliseconds of one dispatch.
  double run(uint mode, float multiplier, float addend, float start) {
    const ProbePush push{mode, shape_.iterations, kTexelCount - 1, 0, multiplier, addend, start, 0.0f};
    const std::array<const vk::Buffer*, FACET_PROBE_BINDING_COUNT> bindings{&out_, &texels_};
    return kernel_.dispatch(bindings, &push, {shape_.workgroups, 1, 1});
  }

  // Checked before any buffer is made for it.
  static const ProbeShape& checked(const vk::Context& context, const ProbeShape& shape) {
    if (shape.workgroups == 0 || shape.workgroups > context.limits().maxComputeWorkGroupCount[0])
      throw Error("probe: " + std::to_string(shape.workgroups) + " workgroups is not a dispatch this device runs");
    if (shape.iterations == 0 || shape.iterations > kMaxIterations || shape.dispatches < 1)
      throw Error("probe: iterations must be 1.." + std::to_string(kMaxIterations) + " and dispatches at least 1");
    return shape;
  }

  std::vector<float> results() const {
    std::vector<float> values(out_.size() / sizeof(float));
    out_.download(values.data(), out_.size());
    return values;
  }

 private:
  static std::vector<std::array<uint32_t, 4>> texel_pattern() {
    std::vector<std::array<uint32_t, 4>> texels(kTexelCount);
    for (uint32_t i = 0; i < kTexelCount; ++i) texels[i] = {i, i * 3u, i * 5u, i * 7u};
    return texels;
  }

  ProbeShape shape_;
  vk::Buffer out_;
  vk::Buffer texels_;
  vk::Kernel kernel_;
};

// The fastest of shape.dispatches dispatches: the rate its `work` per dispatch implies.
double best_rate(const ProbeShape& shape, double work, const std::function<double()>& dispatch_ms) {
  double best_ms = dispatch_ms();
  for (int k = 1; k < shape.dispatches; ++k) best_ms = std::min(best_ms, dispatch_ms());
  if (!(best_ms > 0.0)) throw Error("probe: the device reported no dispatch time");
  return work / (best_ms * 1e-3);
}

}  // namespace

double probe_fmas(const ProbeShape& shape) {
  return static_cast<double>(shape.workgroups) * FACET_PROBE_WORKGROUP * shape.iterations *
         FACET_PROBE_FMAS_PER_ITERATION;
}

double probe_texel_reads(const ProbeShape& shape) {
  return static_cast<double>(shape.workgroups) * FACET_PROBE_WORKGROUP * shape.iterations *
         FACET_PROBE_FETCHES_PER_ITERATION;
}

PeakProbe probe_peak(vk::Context& context, const ProbeShape& shape) {
  ProbeKernel kernel(context, shape);
  kernel.run(FACET_PROBE_MODE_FMA, 1.0f, 1.0f, 0.0f);  // the first dispatch compiles the shader
  PeakProbe peak;
  peak.shape = shape;
  // A multiplier below 1 keeps the chains finite however long they run.
  peak.fma_per_second =
      best_rate(shape, probe_fmas(shape), [&] { return kernel.run(FACET_PROBE_MODE_FMA, 0.999f, 1e-3f, 1e-3f); });
  peak.texel_reads_per_second =
      best_rate(shape, probe_texel_reads(shape), [&] { return kernel.run(FACET_PROBE_MODE_TEXELS, 0.0f, 0.0f, 0.0f); });
  return peak;
}

std::vector<float> count_probe_fmas(vk::Context& context, const ProbeShape& shape) {
  ProbeKernel kernel(context, shape);
  kernel.run(FACET_PROBE_MODE_FMA, 1.0f, 1.0f, 0.0f);
  return kernel.results();
}

}  // namespace facet::gpu
