#version 450
#extension GL_GOOGLE_include_directive : require
// Test probe of lib/microflake_pixel_lobe.glsl on the device: microflake_D_over_pixel for records of three
// vec4, (h, param), (pixel steps), (ndf, -, -, -), the first replaced by (D over the pixel, -, -, -).
#include "lib/microflake_pixel_lobe.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Probes { vec4 probes[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (3u * i + 2u >= uint(probes.length())) return;
  vec4 a = probes[3u * i], b = probes[3u * i + 1u], c = probes[3u * i + 2u];
  probes[3u * i] = vec4(microflake_D_over_pixel(int(c.x), a.w, a.xyz, b), 0.0, 0.0, 0.0);
}
