// The numerical-stability section of the bench report: for each math kernel, its worst error over
// a hard-case suite, for the double twin, the float twin and (where a batch shader exists) the GPU.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vk/context.hpp"

namespace facet::report {

struct StabilityRow {
  std::string kernel;                   // the shared-kernel function
  std::string domain;                   // the hard-case suite
  std::string reference;                // what it is measured against
  std::string measure;                  // how the error is taken
  std::optional<double> f64, f32, gpu;  // worst error; none: not measured (e.g. no batch shader)
};

// A few seconds on lavapipe: a few thousand points per kernel, one batched dispatch per GPU row.
std::vector<StabilityRow> kernel_stability(vk::Context& context);

}  // namespace facet::report
