#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Test probe of render/texture_sampling.glsl: colormap_gaussian(map, mu, sigma) of the direct pass,
// or with what = 1 the spread of the mapped colour around it (colormap_spread, the error estimate's
// eq. 2), with the scene's buffers at their slots (layout/render_layout.glsl), for records (mu, sigma,
// colour map index, what) at the first slot after them, each replaced by (rgb, -). kTextureMethod
// selects filtered (3) or filtered:table (4).
#include "layout/render_layout.glsl"

layout(local_size_x = 64) in;
layout(constant_id = FACET_RENDER_SPEC_TEXTURE_METHOD) const uint kTextureMethod = 4u;
const bool kEstimatesError = false;  // texture_sampling.glsl's own use of the spread is not probed here
// Both kinds of colour map, as in a scene that has both: lanes of step and linear maps side by side.
const bool kHasLinearColormaps = true;
const bool kHasStepColormaps = true;
const bool kWholeMipTexels = false;  // no texture is looked up here
// The walks and searches as loops over each map's own points (the unrolled ones are checked against
// these on scenes: tests/gpu/unrolled_loops_test.cpp).
const uint kStepColormapPoints = 0u;
const uint kLinearColormapPoints = 0u;
const uint kColormapSearchSteps = 32u;  // colormap_at's search: enough for any map
const bool kColormapDivides = true;     // and from a division where a map's record asks for it

#include "render/scene_bindings.glsl"
#include "render/texture_sampling.glsl"

layout(std430, binding = FACET_RENDER_SCENE_BINDING_COUNT) buffer Probes { vec4 probes[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(probes.length())) return;
  vec4 q = probes[i];
  WalkedColormap map = walked_colormap(colormap_record(uint(q.z)));
  vec3 mean = colormap_gaussian(map, q.x, q.y);
  probes[i] = vec4(q.w == 1.0 ? colormap_spread(map, q.x, q.y, mean) : mean, 0.0);
}
