// The host-peak probe (peak_probe.comp; C++: renderer/gpu/peak_probe.hpp): its slots, push constants
// and the work one loop iteration does, shared by GLSL and C++.
#ifndef FACET_PEAK_PROBE_LAYOUT_GLSL
#define FACET_PEAK_PROBE_LAYOUT_GLSL

#define FACET_PROBE_BINDING_OUT 0     // one float per invocation: the sum of its chains
#define FACET_PROBE_BINDING_TEXELS 1  // RGBA32UI texels read by the texel-fetch mode
#define FACET_PROBE_BINDING_COUNT 2
#define FACET_PROBE_WORKGROUP 64

// Each loop iteration of the FMA mode runs one fma on each of 4 independent vec4 chains.
#define FACET_PROBE_FMAS_PER_ITERATION 16
// Each loop iteration of the texel mode fetches this many texels (independent addresses).
#define FACET_PROBE_FETCHES_PER_ITERATION 4

#define FACET_PROBE_MODE_FMA 0u
#define FACET_PROBE_MODE_TEXELS 1u

// Push constants. FMA mode: every chain runs x = fma(x, multiplier, addend) `iterations` times
// from its lane's multiple of `start`, so with start 0, multiplier 1 and addend 1 each lane ends at
// exactly `iterations` (below 2^24) and the written sum counts the FMAs the invocation ran. Texel mode: `texel_mask` + 1 texels
// (a power of two) are read at scattered addresses.
struct ProbePush {
  uint mode;
  uint iterations;
  uint texel_mask;
  uint unused;
  float multiplier;
  float addend;
  float start;
  float unused_f1;
};

#endif
