#version 450
#extension GL_GOOGLE_include_directive : require
// Probe: the pre-integrated colour of query i (direction pair at queries[2i], queries[2i+1])
// into results[i], through render/diffraction_preintegrated.glsl (tests/diffraction/preintegrated_test.cpp).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
layout(std430, binding = 2) readonly buffer Words { uint diffraction_preintegrated_words[]; };
layout(std430, binding = 3) readonly buffer Scales { float diffraction_preintegrated_scales[]; };
layout(push_constant) uniform Probe {
  vec4 grid;     // origin (u, v), spacing (u, v)
  ivec4 shape;   // nu, nv, terms, words
  vec4 scalars;  // w_centre, floor lambda, sigma, h_s
  float R0;
  uint count;
} probe;
uint diffraction_preintegrated_word(uint cell_word, uint i) { return diffraction_preintegrated_words[i]; }
float diffraction_preintegrated_scale(uint i) { return diffraction_preintegrated_scales[i]; }

#include "render/diffraction_preintegrated.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= probe.count) return;
  PreintegratedSource s = PreintegratedSource(
      PreintegratedGrid(probe.grid.xy, probe.grid.zw, probe.shape.x, probe.shape.y, probe.shape.z, probe.shape.w), 0u, 0u,
      probe.scalars.x, probe.scalars.y, probe.scalars.z, probe.scalars.w, probe.R0);
  results[i] = vec4(diffraction_preintegrated_rgb(s, queries[2u * i].xyz, queries[2u * i + 1u].xyz), 0.0);
}
