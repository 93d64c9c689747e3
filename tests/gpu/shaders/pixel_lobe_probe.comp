#version 450
#extension GL_GOOGLE_include_directive : require
// Test probe of lib/microsurface_filter.glsl on the device: normal_density_over_parallelogram for records of
// three vec4, (s0 - mean, step_x), (step_y, -, -), (cov, det_min), the first replaced by (density, -, -, -).
#include "lib/microsurface_filter.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Probes { vec4 probes[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (3u * i + 2u >= uint(probes.length())) return;
  vec4 a = probes[3u * i], b = probes[3u * i + 1u], c = probes[3u * i + 2u];
  probes[3u * i] = vec4(normal_density_over_parallelogram(a.xy, a.zw, b.xy, vec2(0.0), c.xyz, c.w), 0.0, 0.0, 0.0);
}
