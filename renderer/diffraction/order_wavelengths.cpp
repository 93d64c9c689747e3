#include "diffraction/order_wavelengths.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/error.hpp"
#include "diffraction/cie_tables.hpp"
#include "diffraction/diffraction_eval.hpp"

namespace facet::diffraction {

namespace {

using namespace kernels::f64;

// The largest divisor P of M such that shifting the field by M / P samples along (dx, dy) leaves it unchanged.
int repeats_along(const Grating& g, int dx, int dy) {
  const int M = g.samples;
  const auto [lo, hi] = std::minmax_element(g.height_nm.begin(), g.height_nm.end());
  const double tolerance = 1e-9 * std::max(*hi - *lo, 1e-300);
  auto at = [&](int x, int y) { return g.height_nm[static_cast<size_t>(y % M) * M + x % M]; };
  for (int P = M; P > 1; --P) {
    if (M % P != 0) continue;
    const int s = M / P;
    bool same = true;
    for (int y = 0; y < M && same; ++y)
      for (int x = 0; x < M && same; ++x) same = std::abs(at(x + s * dx, y + s * dy) - at(x, y)) <= tolerance;
    if (same) return P;
  }
  return 1;
}

// F.10: orders per axis whose reach (widened by a pixel's, O3) meets the segment k (u, v) at |(u, v)| = 2, multiplied.
double worst_orders(const DiffractionOrderLattice& L, double pixel_reach) {
  const double extent = 2.0 * (L.k_max - L.k_min) + 2.0 * (L.reach + pixel_reach);
  return (extent / L.frequency.x + 1.0) * (extent / L.frequency.y + 1.0);
}

// F.11: a point k (u, v) lies within the reach of pi rho^2 / (f_x f_y) orders on average (lattice
// points in a disc of radius rho around a uniformly placed point), and each of them is integrated
// over the pixel's wavelengths with steps of at most max_step.
double expected_nodes(const DiffractionOrderLattice& L) {
  const double overlap = std::numbers::pi * L.reach * L.reach / (L.frequency.x * L.frequency.y);
  return overlap * (kCieLambdaMaxNm - kCieLambdaMinNm) / L.max_step;
}

// F.13: order j's interval spans len_j <= 2 rho / |uv| in k, i.e. lambda_lo lambda_hi rho / (pi |uv|) in
// wavelength, with the smaller of two steps: the peak's, peak_step lambda_lo^2 / (2 pi sqrt2 sigma |uv|),
// and max_step. So nodes_j <= len_j / step_j + 1 <= 2 sqrt2 rho sigma (lambda_max / lambda_min) / peak_step
// + len_j / max_step + 1. A wavelength lies in the intervals of at most O orders (the lattice points
// within rho of one point: O <= prod (floor(2 rho / f) + 1)), so sum_j len_j <= O (lambda_max -
// lambda_min), and over the F.10 candidates C: nodes <= C (peak bound + 1) + O range / max_step.
double most_nodes(const DiffractionOrderLattice& L, double candidates) {
  const double per_peak =
      2.0 * std::sqrt(2.0) * L.reach * L.sigma_nm * (kCieLambdaMaxNm / kCieLambdaMinNm) / L.peak_step;
  const glm::dvec2 overlap = glm::floor(2.0 * L.reach / L.frequency) + 1.0;
  return std::ceil(candidates) * (per_peak + 1.0) +
         overlap.x * overlap.y * (kCieLambdaMaxNm - kCieLambdaMinNm) / L.max_step;
}

}  // namespace

PatchRepeats patch_repeats(const Grating& grating) {
  return {repeats_along(grating, 1, 0), repeats_along(grating, 0, 1)};
}

OrderWavelengths plan_order_wavelengths(const Grating& grating, const SpectralTables& tables, double tolerance,
                                        Illuminant light, WavelengthSamples fallback) {
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw Error("order wavelengths: tolerance must lie in (0, 1)");
  OrderWavelengths plan;
  const PatchRepeats repeats = patch_repeats(grating);
  DiffractionOrderLattice& L = plan.lattice;
  L.repeats = glm::ivec2(repeats.x, repeats.y);
  L.frequency = (2.0 * std::numbers::pi) * glm::dvec2(L.repeats) / tables.period_nm;
  L.sigma_nm = tables.sigma_nm;
  L.reach = std::sqrt(2.0 * std::log(1.0 / tolerance)) / tables.sigma_nm;
  L.k_min = (2.0 * std::numbers::pi) / kCieLambdaMaxNm;
  L.k_max = (2.0 * std::numbers::pi) / kCieLambdaMinNm;
  // F.9: the midpoint rule's error on a Gaussian of deviation s at step h is 2 exp(-2 pi^2 s^2 / h^2) <= tol / 2,
  // and the observer alone needs observer_spacing. Both halved: a peak times the observer is
  // neither (measured: 5e-3 of the colour at the full steps, 2e-4 at half, tol 1e-3).
  L.peak_step = 0.5 * std::numbers::pi * std::sqrt(2.0 / std::log(4.0 / tolerance));
  L.max_step = 0.5 * observer_spacing(tolerance, light);
  // O2 drops the window sum's cross terms between orders, exp(-sigma^2 f^2 / 4) of the peak at most: where they
  // may pass the tolerance, a pixel keeps the orders at its centre (pixel_reach 0).
  const double spacing = std::min(L.frequency.x, L.frequency.y);
  const bool separated = L.sigma_nm * L.sigma_nm * spacing * spacing / 4.0 >= std::log(1.0 / tolerance);
  L.pixel_reach = separated ? kPixelWindows / L.sigma_nm : 0.0;
  L.pixel_budget = kPixelNodeBudget;
  plan.worst_orders = worst_orders(L, 0.0);
  plan.worst_orders_over_pixel = worst_orders(L, L.pixel_reach);
  plan.expected_nodes = expected_nodes(L);
  plan.most_nodes = most_nodes(L, plan.worst_orders);
  plan.restricted =
      plan.worst_orders <= kMaxOrdersPerPixel && plan.expected_nodes < static_cast<double>(fallback.lambda_nm.size());
  plan.lambda0_nm = kCieLambdaMinNm;
  for (double lambda = kCieLambdaMinNm; lambda <= kCieLambdaMaxNm; lambda += 1.0)
    plan.observer.push_back(xyz_density(lambda, light));
  plan.fallback = std::move(fallback);
  return plan;
}

glm::dvec3 evaluate_orders(const SpectralTables& tables, const OrderWavelengths& plan, const glm::dvec3& wi,
                           const glm::dvec3& wr, std::optional<glm::dvec4> pixel_steps) {
  if (!plan.restricted)  // the spectral path, as the shader runs it
    return integrate_linear_srgb(plan.fallback, [&](double l) { return evaluate_taylor(tables, {wi, wr, l}).brdf; });
  const DiffractionOrderLattice& L = plan.lattice;
  const glm::dvec2 uv = -glm::dvec2(wi.x + wr.x, wi.y + wr.y);
  const bool over_pixel = diffraction_orders_over_pixel(L, pixel_steps.has_value());
  const glm::dvec4 steps = over_pixel ? diffraction_pixel_steps(L, *pixel_steps) : glm::dvec4(0.0);
  const glm::dvec2 half_extent = diffraction_pixel_half_extent(steps);
  const double r = glm::length(half_extent);
  // Over the pixel each order's own bin weighed by its window's mean (O2), else the window sum and F.8's share.
  auto weighed = [&](double lambda, glm::ivec2 j) {
    if (over_pixel)
      return evaluate_bin(tables, {wi, wr, lambda}, j * L.repeats).brdf *
             diffraction_window_over_pixel(L, uv, steps, j, 2.0 * std::numbers::pi / lambda);
    return evaluate_taylor(tables, {wi, wr, lambda}, L.repeats).brdf * diffraction_order_share(L, uv, lambda, j);
  };
  const DiffractionOrderSpan span = diffraction_order_span(L, uv, half_extent);
  int wanted = 0;
  for (int c = 0; c < diffraction_order_candidates(span); ++c)
    wanted += diffraction_order_interval(L, uv, diffraction_order_candidate(span, c), r).nodes;
  const int budget = over_pixel ? L.pixel_budget : wanted;
  const int entries = static_cast<int>(plan.observer.size());
  glm::dvec3 xyz(0.0);
  for (int c = 0; c < diffraction_order_candidates(span); ++c) {  // the shader's order of summation
    const glm::ivec2 j = diffraction_order_candidate(span, c);
    const DiffractionOrderInterval I =
        diffraction_order_interval_within(diffraction_order_interval(L, uv, j, r), wanted, budget);
    for (int i = 0; i < I.nodes; ++i) {
      const double lambda = diffraction_order_lambda(I, i);
      const DiffractionObserverLookup o = diffraction_observer_lookup(lambda, plan.lambda0_nm, entries);
      if (!o.valid) continue;
      const glm::dvec3 observer = glm::mix(plan.observer[o.index], plan.observer[o.index + 1], o.f);
      xyz += (weighed(lambda, j) * I.step) * observer;
    }
  }
  return spectral_xyz_to_linear_srgb(xyz);
}

}  // namespace facet::diffraction
