// Where the texels of a MIP level sit, for bilinear lookups of any level of a periodic texture whose
// size need not be a power of two (docs/colormap_filtering.md). Level l of a chain of level-0 size
// W has count = ceil(W / 2^l) texels per axis (precompute::build_moment_mips, shaders/build_mips.comp):
// texel i covers the level-0 texels [i span, min((i + 1) span, W)), span = 2^l, and holds their mean,
// so its centre is the centre of that range. In level-texel units the period is e = W / span and
// the centres are i + 1/2, except the last, partial one at ((count - 1) + e) / 2. Lookups interpolate
// linearly between the two centres around the point, across the period at both ends. With W a
// multiple of span (always at level 0) this is the usual (i + 1/2) grid.
#ifndef FACET_MIP_GRID_GLSL
#define FACET_MIP_GRID_GLSL
#include "lib/prelude.glsl"

// Texels i0 and i1 = the next one (both in [0, count)) and the weight of i1.
struct MipAxisTaps {
  int i0;
  int i1;
  real w1;
};

inline real mip_texel_centre(int i, int count, real e) {
  return i < count - 1 ? real(i) + real(0.5) : (real(count - 1) + e) * real(0.5);
}

// u: texture coordinate (period 1); size0: W; span: 2^l; count: ceil(W / span). NaN and infinite u
// give texel 0.
inline MipAxisTaps mip_axis_taps(real u, int size0, int span, int count) {
  real e = real(size0) / real(span);
  real wrapped = u - floor(u);
  real x = wrapped >= real(0) && wrapped < real(1) ? wrapped * e : real(0);
  real last = mip_texel_centre(count - 1, count, e);
  int i = min(int(floor(x - real(0.5))), count - 1);
  if (i == count - 2 && x >= last) i = count - 1;  // past the partial texel's centre
  real left = i < 0 ? last - e : mip_texel_centre(i, count, e);
  real right = i + 1 < count ? mip_texel_centre(i + 1, count, e) : mip_texel_centre(0, count, e) + e;
  real w1 = clamp((x - left) / (right - left), real(0), real(1));
  return MipAxisTaps(i < 0 ? count - 1 : i, i + 1 < count ? i + 1 : 0, w1);
}

// mip_axis_taps for a level whose texels are all whole (W a multiple of span, so e = count: every level
// of a power-of-two size): centres at i + 1/2, neighbours one apart, so no partial texel, no clamp and no
// division. It performs the general function's remaining operations in the same order and so returns
// its very taps and weight (tests/kernels/mip_grid_test.cpp), at a third of its arithmetic.
inline MipAxisTaps mip_axis_taps_whole(real u, int count) {
  real wrapped = u - floor(u);
  real x = wrapped >= real(0) && wrapped < real(1) ? wrapped * real(count) : real(0);
  int i = int(floor(x - real(0.5)));
  return MipAxisTaps(i < 0 ? count - 1 : i, i + 1 < count ? i + 1 : 0, x - (real(i) + real(0.5)));
}

#endif
