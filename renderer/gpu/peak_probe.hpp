// The host's own peak, measured by facet itself (shaders/peak_probe.comp): float32 FMA throughput of
// the device and its texel-fetch throughput, each the best of a few dispatches. `facet info --probe`
// prints it and `facet bench` records it, to set every method's time against the host's limit
// (docs/report.md, the roofline).
#pragma once

#include <cstdint>
#include <vector>

#include "vk/context.hpp"

namespace facet::gpu {

struct ProbeShape {
  uint32_t workgroups = 4096;  // of FACET_PROBE_WORKGROUP invocations: 1.07 G FMAs per dispatch
  uint32_t iterations = 256;   // per invocation (lavapipe ends loops after 65 535 iterations in all)
  int dispatches = 5;           // best of
};

struct PeakProbe {
  double fma_per_second = 0.0;          // float32 FMAs (one per vector lane)
  double texel_reads_per_second = 0.0;  // RGBA32UI texel fetches from a uniform texel buffer
  ProbeShape shape;
};

// Throws facet::Error for a shape the device cannot run (no workgroups, too many loop iterations).
PeakProbe probe_peak(vk::Context& context, const ProbeShape& shape = {});

// One dispatch of the FMA chains with multiplier 1 and addend 1: each invocation's result is the
// number of FMAs it ran (exact below 2^24), for tests to compare with the count probe_peak assumes.
std::vector<float> count_probe_fmas(vk::Context& context, const ProbeShape& shape);

// The FMAs and texel fetches one dispatch of `shape` does, as probe_peak counts them.
double probe_fmas(const ProbeShape& shape);
double probe_texel_reads(const ProbeShape& shape);

}  // namespace facet::gpu
