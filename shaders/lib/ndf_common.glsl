// Small helpers shared by the normal distributions (ndf_*.glsl): log(1+x) - x without cancellation
// near 0, and a hash stream for rejection samplers that need more than the two uniforms they get.
#ifndef FACET_NDF_COMMON_GLSL
#define FACET_NDF_COMMON_GLSL
#include "lib/prelude.glsl"

// log(1+x) - x. For |x| <= 1/2 with z = x/(2+x): log(1+x) = 2 atanh z = 2(z + z^3/3 + ...) and
// x = 2z/(1-z), so log(1+x) - x = -2z^2/(1-z) + 2 sum_{k>=1} z^(2k+1)/(2k+1); no cancellation.
inline real ndf_log1p_minus_x(real x) {
  if (abs(x) > real(0.5)) return log(real(1) + x) - x;
  real z = x / (real(2) + x);
  real z2 = z * z;
#if REAL_IS_DOUBLE
  const int terms = 17;  // |z| <= 1/3: (1/3)^35 < 1e-16
#else
  const int terms = 7;  // (1/3)^15 < 1e-7
#endif
  real sum = real(0);
  for (int k = terms; k >= 1; --k) sum = z2 * (real(1) / real(2 * k + 1) + sum);
  return real(-2) * z2 / (real(1) - z) + real(2) * z * sum;
}

// Hash stream (PCG-style output permutation of an LCG state) for rejection loops. The first
// attempt of a sampler uses the caller's uniforms; later attempts draw from this stream.
struct NdfRng {
  uint state;
};

inline NdfRng ndf_rng_seed(real2 u) {
  uint a = uint(clamp(u.x, real(0), real(1)) * real(4294967040.0));
  uint b = uint(clamp(u.y, real(0), real(1)) * real(4294967040.0));
  return NdfRng(a * 747796405u + (b ^ 2891336453u));
}

inline NdfRng ndf_rng_next(NdfRng r) { return NdfRng(r.state * 747796405u + 2891336453u); }

// Uniform in [0, 1) from the current state (24 bits, exact in float and double).
inline real ndf_rng_uniform(NdfRng r) {
  uint w = ((r.state >> ((r.state >> 28u) + 4u)) ^ r.state) * 277803737u;
  w = (w >> 22u) ^ w;
  return real(w >> 8u) * real(5.9604644775390625e-8);
}

// The next two uniforms of the stream (a rejection sampler's fresh proposal); advances it twice.
struct NdfRngPair {
  NdfRng rng;
  real2 xi;
};

inline NdfRngPair ndf_rng_next_pair(NdfRng r) {
  NdfRng a = ndf_rng_next(r);
  NdfRng b = ndf_rng_next(a);
  return NdfRngPair(b, real2(ndf_rng_uniform(a), ndf_rng_uniform(b)));
}

#endif
