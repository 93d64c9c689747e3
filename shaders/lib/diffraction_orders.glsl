// Order-restricted wavelengths (after Single 2014's "NMM" shader; derivation and tests:
// docs/diffraction_fast_paths.md). A grating whose height repeats with periods (T_x, T_y) has DFT
// power only on the lattice alpha_j = (2 pi j_x / T_x, 2 pi j_y / T_y). Seen through the coherence
// window, order j reaches (u, v) only for the wavenumbers k with |k (u, v) - alpha_j| <= rho
// (eq. F.7: a short interval around the grating equation k = alpha_j.(u,v) / |(u,v)|^2). The colour
// integral is taken over those intervals only, each with a midpoint rule in wavelength fine enough for its peak
// (eq. F.9), and a partition of unity over the orders (eq. F.8) keeps overlapping intervals from
// counting any wavenumber twice. Each side evaluates the per-wavelength BRDF (diffraction_brdf.glsl)
// at the nodes and looks up the observer table itself. Over a pixel (`filtered`; eqs. O1-O3) the pixel's
// (u, v) is a parallelogram: the intervals and the span widen to every wavenumber at which some of it meets
// an order's reach, and each order's window is averaged over it (diffraction_window_over_pixel).
#ifndef FACET_DIFFRACTION_ORDERS_GLSL
#define FACET_DIFFRACTION_ORDERS_GLSL
#include "lib/prelude.glsl"
#include "lib/normal_over_parallelogram.glsl"

struct DiffractionOrderLattice {
  real2 frequency;   // 2 pi / (T_x, T_y): the spacing of the grating's orders [1/nm]
  real sigma_nm;     // coherence window
  real reach;        // rho = sqrt(2 ln(1/tol)) / sigma: beyond it a window weight is below tol [1/nm]
  real k_min;        // wavenumbers of the observer's range
  real k_max;
  real peak_step;    // midpoint step of a Gaussian peak in units of its standard deviation (eq. F.9)
  real max_step;     // largest step in wavelength that still resolves the observer and the light [nm]
  ivec2 repeats;     // (P_x, P_y): the patch holds P periods per axis, so its DFT bins are non-zero only at multiples of P
  real pixel_reach;  // over a pixel: k_max times the radius of the (u, v) disc it may cover, at most [1/nm] (O3);
                     // 0: orders too close for O2's model, a pixel takes them at its centre
  int pixel_budget;  // over a pixel: midpoint nodes of all its orders, at most (O3)
};

// Whether a filtered method takes the pixel's mean of this lattice's orders: not where they lie too close for
// O2 (pixel_reach 0), whose pixels keep the coherent window sum at their centre.
inline bool diffraction_orders_over_pixel(DiffractionOrderLattice L, bool filtered) {
  return filtered && L.pixel_reach > real(0);
}

// Half the extent per axis of the pixel's (u, v), uv + a steps.xy + b steps.zw (a, b in [-1/2, 1/2]), from
// the change of (u, v) per pixel step along x (xy) and y (zw).
inline real2 diffraction_pixel_half_extent(real4 steps) {
  return real(0.5) * (abs(real2(steps.x, steps.y)) + abs(real2(steps.z, steps.w)));
}

// The steps shrunk alike so that the disc holding the pixel's parallelogram reaches at most L.pixel_reach / k_max
// (eq. O3: a pixel spanning more, at a silhouette, is averaged over that much of itself).
inline real4 diffraction_pixel_steps(DiffractionOrderLattice L, real4 steps) {
  real r = length(diffraction_pixel_half_extent(steps));
  real most = L.pixel_reach / L.k_max;
  return r > most ? steps * (most / r) : steps;
}

// The orders j in [lo, hi] (per axis) whose reach can meet the segment k (u, v), k in [k_min, k_max].
struct DiffractionOrderSpan {
  ivec2 lo;
  ivec2 hi;
};

// half_extent: the pixel's (u, v) lies within uv +- half_extent (0 for a point).
inline DiffractionOrderSpan diffraction_order_span(DiffractionOrderLattice L, real2 uv, real2 half_extent) {
  real2 lo = uv - half_extent, hi = uv + half_extent;
  real2 a = min(min(L.k_min * lo, L.k_max * lo), min(L.k_min * hi, L.k_max * hi)) - real2(L.reach, L.reach);
  real2 b = max(max(L.k_min * lo, L.k_max * lo), max(L.k_min * hi, L.k_max * hi)) + real2(L.reach, L.reach);
  return DiffractionOrderSpan(ivec2(ceil(a / L.frequency)), ivec2(floor(b / L.frequency)));
}

// The candidates of a span as one list, row by row (j_y outer, j_x inner): their count (0 for an
// empty span) and the c-th, c < count.
// One flat index lets a caller walk all orders' nodes in a single loop (render/diffraction_orders.glsl).
inline int diffraction_order_candidates(DiffractionOrderSpan s) {
  ivec2 n = max(s.hi - s.lo + ivec2(1, 1), ivec2(0, 0));
  return n.x * n.y;
}

inline ivec2 diffraction_order_candidate(DiffractionOrderSpan s, int c) {
  int width = s.hi.x - s.lo.x + 1;
  return s.lo + ivec2(c % width, c / width);
}

// The midpoint nodes of order j in wavelength: lambda = lambda_lo + (i + 1/2) step, i < nodes
// (nodes = 0: order j does not reach (u, v)).
struct DiffractionOrderInterval {
  real lambda_lo;
  real step;
  int nodes;
};

// r: the pixel's (u, v) lies within the disc of radius r about uv (0 for a point).
inline DiffractionOrderInterval diffraction_order_interval(DiffractionOrderLattice L, real2 uv, ivec2 j, real r) {
  real2 alpha = real2(j) * L.frequency;
  // |k uv - alpha|^2 <= rho^2  <=>  |uv|^2 k^2 - 2 (uv.alpha) k + |alpha|^2 - rho^2 <= 0   (F.7); over the
  // disc, |k uv - alpha| <= rho + k r  <=>  (|uv|^2 - r^2) k^2 - 2 (uv.alpha + rho r) k + |alpha|^2 - rho^2 <= 0 (O1)
  real uu = dot(uv, uv);
  real a = uu - r * r;
  real b = dot(uv, alpha) + L.reach * r;
  real c = dot(alpha, alpha) - L.reach * L.reach;
  real lo = L.k_min;
  real hi = L.k_max;
  if (a > real(0)) {
    real disc = b * b - a * c;
    real root = sqrt(max(disc, real(0)));
    lo = disc < real(0) ? L.k_max : max(lo, (b - root) / a);
    hi = disc < real(0) ? L.k_min : min(hi, (b + root) / a);
  } else if (c > real(0) && !(r > real(0))) {
    hi = lo;  // at (u, v) = 0 only the orders within rho of the origin are seen, at every k
  }  // a disc holding (u, v) = 0: every k (the set is the complement of an interval; its hull)
  if (!(hi > lo)) return DiffractionOrderInterval(real(0), real(0), 0);
  // |S|^2 carries the squared window exp(-sigma^2 |k uv - alpha|^2): a Gaussian in k of standard
  // deviation 1 / (sqrt(2) sigma |uv|), i.e. lambda^2 / (2 pi) times that in wavelength, narrowest
  // at the interval's short end and, over a pixel, at its (u, v) farthest from 0.
  real farthest = sqrt(uu) + r;
  real lambda_lo = real(2) * FACET_PI / hi;
  real lambda_hi = real(2) * FACET_PI / lo;
  real deviation = farthest > real(0)
                       ? lambda_lo * lambda_lo / (real(2) * FACET_PI * FACET_SQRT2 * L.sigma_nm * farthest)
                       : L.max_step;
  real step = min(L.peak_step * deviation, L.max_step);
  int nodes = int(ceil((lambda_hi - lambda_lo) / step));
  return DiffractionOrderInterval(lambda_lo, (lambda_hi - lambda_lo) / real(nodes), nodes);
}

// O3: a pixel whose orders' intervals hold `total` nodes, more than `budget`, gets each order's nodes cut
// alike to floor(nodes budget / total), at least 1, over the same interval (a coarser midpoint rule): its
// walk then takes at most budget + (its orders) nodes.
inline DiffractionOrderInterval diffraction_order_interval_within(DiffractionOrderInterval I, int total, int budget) {
  if (total <= budget || I.nodes == 0) return I;
  int nodes = max(1, int(real(I.nodes) * (real(budget) / real(total))));
  return DiffractionOrderInterval(I.lambda_lo, I.step * (real(I.nodes) / real(nodes)), nodes);
}

inline real diffraction_order_lambda(DiffractionOrderInterval I, int i) {
  return I.lambda_lo + (real(i) + real(0.5)) * I.step;
}

// Eq. O2: order j's squared window exp(-sigma^2 |k uv - alpha_j|^2) averaged over the pixel's (u, v),
// uv + a steps.xy + b steps.zw (a, b uniform in [-1/2, 1/2]). In uv it is 2 pi c N(uv; alpha_j / k, c I),
// c = 1 / (2 sigma^2 k^2), whose mean over the parallelogram normal_density_over_parallelogram takes
// (exact for a point and for orthogonal steps).
inline real diffraction_window_over_pixel(DiffractionOrderLattice L, real2 uv, real4 steps, ivec2 j, real k) {
  real c = real(0.5) / (L.sigma_nm * L.sigma_nm * k * k);
  real2 centre = real2(j) * L.frequency / k;
  return real(2) * FACET_PI * c *
         normal_density_over_parallelogram(uv, real2(steps.x, steps.y), real2(steps.z, steps.w), centre,
                                           real3(c, c, real(0)), c * c);
}

// Eq. F.8: order j's share of the wavenumber k = 2 pi / lambda, e_j / sum_j' e_j' over the orders
// within rho of k (u, v) (e = the window weight exp(-sigma^2 |k uv - alpha|^2 / 2)). Written as
// 1 / (1 + sum_{j' != j} e_j' / e_j) with the ratios taken in the exponent, so it stays in (0, 1]
// where every weight underflows; j itself is among those orders at every node of its interval.
inline real diffraction_order_share(DiffractionOrderLattice L, real2 uv, real lambda_nm, ivec2 j) {
  real2 alpha = (real(2) * FACET_PI / lambda_nm) * uv;
  ivec2 nearest = ivec2(floor(alpha / L.frequency + real2(real(0.5), real(0.5))));
  ivec2 radius = ivec2(floor(real2(L.reach, L.reach) / L.frequency + real2(real(0.5), real(0.5))));
  real half_s2 = real(-0.5) * L.sigma_nm * L.sigma_nm;
  real2 own = alpha - real2(j) * L.frequency;
  real own_d2 = dot(own, own);
  real others = real(0);
  for (int dy = -radius.y; dy <= radius.y; ++dy) {
    for (int dx = -radius.x; dx <= radius.x; ++dx) {
      ivec2 other = nearest + ivec2(dx, dy);
      real2 d = alpha - real2(other) * L.frequency;
      others += (other == j) ? real(0) : exp(half_s2 * (dot(d, d) - own_d2));
    }
  }
  return real(1) / (real(1) + others);
}

// The observer table: (xbar, ybar, zbar) S(lambda) / Y_white at 1 nm steps from lambda_0; linear
// interpolation between entries `index` and `index + 1` (valid false outside the table).
struct DiffractionObserverLookup {
  int index;
  real f;
  bool valid;
};

inline DiffractionObserverLookup diffraction_observer_lookup(real lambda_nm, real lambda0_nm, int entries) {
  real t = lambda_nm - lambda0_nm;
  int i = int(floor(t));
  bool valid = t >= real(0) && i < entries - 1;
  int index = clamp(i, 0, entries - 2);
  return DiffractionObserverLookup(index, t - real(index), valid);
}

#endif
