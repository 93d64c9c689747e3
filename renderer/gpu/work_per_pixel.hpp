// Each method's work per pixel, counted by running its render pass once with the work counters
// compiled in (gpu/work_counter.hpp, kCountsWork in render/direct_pass.glsl): what `facet bench`
// sets against the host's peak (gpu/peak_probe.hpp) for its roofline.
#pragma once

#include "gpu/direct_pass.hpp"
#include "gpu/render_method.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

struct WorkCount {
  Image per_pixel;  // r: FMA-equivalents, g: texel fetches, each summed over the pixel's samples
  double fma_per_pixel = 0.0, reads_per_pixel = 0.0;  // their means over the frame
};

// `method` (its AOVs dropped) on `scene` from its camera at width x height.
WorkCount count_work(vk::Context& context, const Scene& scene, RenderMethod method, int width, int height);

}  // namespace facet::gpu
