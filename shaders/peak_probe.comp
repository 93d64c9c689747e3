#version 450
#extension GL_GOOGLE_include_directive : require
// The host's own peak (facet info --probe, facet bench): float32 FMA throughput from long chains of
// independent FMAs, and texel-fetch throughput from a uniform texel buffer (layout/peak_probe_layout.glsl).
#include "layout/peak_probe_layout.glsl"

layout(local_size_x = FACET_PROBE_WORKGROUP) in;
layout(std430, binding = FACET_PROBE_BINDING_OUT) writeonly buffer Out { float results[]; };
layout(binding = FACET_PROBE_BINDING_TEXELS) uniform usamplerBuffer probe_texels;
layout(push_constant) uniform Push { ProbePush probe; };

// Four vec4 chains, no chain reading another: lavapipe runs 8 invocations per AVX2 register, so they
// are 16 registers of independent FMAs, enough to cover the FMA latency on both ports. Each lane
// starts from its own multiple of `start` (0 when counting), so the JIT cannot merge lanes that it
// would otherwise see compute the same value. The sum is written so that no chain is dead.
float fma_chains() {
  float s0 = probe.start;
  vec4 a0 = vec4(0.0, 1.0, 2.0, 3.0) * s0, a1 = vec4(4.0, 5.0, 6.0, 7.0) * s0;
  vec4 a2 = vec4(8.0, 9.0, 10.0, 11.0) * s0, a3 = vec4(12.0, 13.0, 14.0, 15.0) * s0;
  vec4 b = vec4(probe.multiplier), c = vec4(probe.addend);
  for (uint k = 0u; k < probe.iterations; ++k) {
    a0 = fma(a0, b, c);
    a1 = fma(a1, b, c);
    a2 = fma(a2, b, c);
    a3 = fma(a3, b, c);
  }
  vec4 s = (a0 + a1) + (a2 + a3);
  return (s.x + s.y) + (s.z + s.w);
}

// Four fetches per iteration at addresses spread by an odd multiplier (a permutation of the texels).
float texel_fetches() {
  uvec4 sum = uvec4(0u);
  uint at = gl_GlobalInvocationID.x * 2654435761u;
  for (uint k = 0u; k < probe.iterations; ++k) {
    sum += texelFetch(probe_texels, int(at & probe.texel_mask));
    sum += texelFetch(probe_texels, int((at + 1013u) & probe.texel_mask));
    sum += texelFetch(probe_texels, int((at + 2029u) & probe.texel_mask));
    sum += texelFetch(probe_texels, int((at + 3037u) & probe.texel_mask));
    at = at * 747796405u + 2891336453u;
  }
  return float((sum.x ^ sum.y ^ sum.z ^ sum.w) & 1u);
}

void main() {
  results[gl_GlobalInvocationID.x] = probe.mode == FACET_PROBE_MODE_FMA ? fma_chains() : texel_fetches();
}
