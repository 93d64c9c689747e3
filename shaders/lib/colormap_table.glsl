// Where a prefiltered colour map T(mu, sigma) is sampled and how a lookup blends it
// (renderer/precompute/prefiltered_colormap.cpp builds it, docs/colormap_filtering.md). Nodes:
// mu_i = mu_min + (mu_max - mu_min) i/(I - 1), sigma_j = sigma_max (j/(J - 1))^2 (quadratic, so small
// sigma, where T changes fastest, is resolved). Entry (i, j) is at index j I + i. The GPU reads the
// four corners from a buffer and the CPU from a vector; both take the index and weight math from here.
#ifndef FACET_COLORMAP_TABLE_GLSL
#define FACET_COLORMAP_TABLE_GLSL
#include "lib/prelude.glsl"

struct ColormapTableGrid {
  real mu_min;
  real mu_max;
  real sigma_max;
  int mu_count;     // I >= 2
  int sigma_count;  // J >= 2
};

// The cell (i0, j0) holding (mu, sigma) and the bilinear weights inside it. mu is clamped to
// [mu_min, mu_max] (the builder adds margins where T is the end colour), sigma to [0, sigma_max];
// NaN goes to the low end.
struct ColormapTableTaps {
  int i0;
  int j0;
  real w_mu;
  real w_sigma;
};

inline real colormap_table_mu(ColormapTableGrid g, int i) {
  return g.mu_min + (g.mu_max - g.mu_min) * (real(i) / real(g.mu_count - 1));
}

inline real colormap_table_sigma(ColormapTableGrid g, int j) {
  real f = real(j) / real(g.sigma_count - 1);
  return g.sigma_max * f * f;
}

inline int colormap_table_index(ColormapTableGrid g, int i, int j) {
  return j * g.mu_count + i;
}

inline ColormapTableTaps colormap_table_taps(ColormapTableGrid g, real mu, real sigma) {
  real u = (mu - g.mu_min) / (g.mu_max - g.mu_min);
  u = u >= real(0) ? min(u, real(1)) : real(0);  // also NaN -> 0
  real v = sigma / g.sigma_max;
  v = v >= real(0) ? sqrt(min(v, real(1))) : real(0);  // inverse of the quadratic spacing
  real x = u * real(g.mu_count - 1);
  real y = v * real(g.sigma_count - 1);
  int i0 = min(int(floor(x)), g.mu_count - 2);
  int j0 = min(int(floor(y)), g.sigma_count - 2);
  return ColormapTableTaps(i0, j0, x - real(i0), y - real(j0));
}

// t00 = T(i0, j0), t10 = T(i0 + 1, j0), t01 = T(i0, j0 + 1), t11 = T(i0 + 1, j0 + 1).
inline real3 colormap_table_blend(real3 t00, real3 t10, real3 t01, real3 t11, ColormapTableTaps taps) {
  return mix(mix(t00, t10, taps.w_mu), mix(t01, t11, taps.w_mu), taps.w_sigma);
}

#endif
