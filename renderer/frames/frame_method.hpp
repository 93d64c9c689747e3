// What renders a frame: a GPU method (`--method`, with its diffraction overrides) or the CPU
// reference with its sampling settings.
#pragma once

#include <cstdint>
#include <variant>

#include "gpu/render_method.hpp"

namespace facet::frames {

// The CPU reference's settings (docs/reference.md); the seed is an int64, as the CLI and job files
// take it and the metadata records it.
struct ReferenceMethod {
  int grid = 32;  // N: N x N jittered rays per pixel
  std::int64_t seed = 1;
  int threads = 0;  // 0: all cores; the image does not depend on it
  AovSet aovs{};    // depth, normal, uv (`--aov`); the reference has no error estimate
};

using FrameMethod = std::variant<gpu::RenderMethod, ReferenceMethod>;

}  // namespace facet::frames
