// The order-restricted colour (lib/diffraction_orders.glsl; the C++ twin is evaluate_orders in
// renderer/diffraction/order_wavelengths.cpp): the per-wavelength Taylor BRDF
// (render/diffraction_taylor.glsl) at the nodes of each reaching order's interval, weighted by the
// order's share, the node's step and the observer. The includer defines
// `vec2 diffraction_coefficient_at(uint)` and `vec4 diffraction_observer_at(uint)` (XYZ per nm, xyz_density).
// Gratings not worth restricting (F.10, F.11) never reach this path (the host picks the spectral one).
#ifndef FACET_RENDER_DIFFRACTION_ORDERS_GLSL
#define FACET_RENDER_DIFFRACTION_ORDERS_GLSL
#include "lib/diffraction_orders.glsl"
#include "lib/spectral_srgb.glsl"
#include "render/diffraction_taylor.glsl"

struct OrderObserver {
  uint first;     // of the material's table in the observer entries
  int entries;    // 1 nm entries from lambda0
  float lambda0_nm;
};

// Lavapipe runs 8 invocations (neighbouring pixels) in lock-step: a loop runs until its last lane
// leaves it, so nested loops over orders and nodes cost the sum over orders of the busiest lane's
// nodes. Here every lane walks its own nodes in ONE loop of its total count (a cheap first pass
// over the candidates' intervals), moving on to its next order whenever one is used up; a group
// then costs its busiest lane's total. Same terms, same order as evaluate_orders (the C++ twin).
// filtered (a constant of each call site): the colour's mean over the pixel whose (u, v) moves by
// pixel_steps.xy and .zw per pixel step (eqs. O1-O3, docs/diffraction_fast_paths.md): each order's own
// bin weighed by its window's mean over the pixel, orders apart (the window sum's cross terms and the
// shares of F.8 belong to overlapping orders, which a grating this path runs does not have: F.11).
vec3 diffraction_orders_xyz(DiffractionOrderLattice L, DiffractionTableInfo info, uint first_coefficient,
                            OrderObserver o, vec3 wi, vec3 wr, bool filtered, vec4 pixel_steps) {
  bool over_pixel = diffraction_orders_over_pixel(L, filtered);
  vec2 uv = -(wi.xy + wr.xy);
  vec4 steps = over_pixel ? diffraction_pixel_steps(L, pixel_steps) : vec4(0.0);
  vec2 half_extent = diffraction_pixel_half_extent(steps);
  float r = length(half_extent);
  DiffractionOrderSpan span = diffraction_order_span(L, uv, half_extent);
  int candidates = diffraction_order_candidates(span);
  int wanted = 0;
  for (int c = 0; c < candidates; ++c)
    wanted += diffraction_order_interval(L, uv, diffraction_order_candidate(span, c), r).nodes;
  int budget = over_pixel ? L.pixel_budget : wanted;
  int total = wanted;
  if (wanted > budget) {  // O3: every order's nodes cut alike
    total = 0;
    for (int c = 0; c < candidates; ++c)
      total += diffraction_order_interval_within(diffraction_order_interval(L, uv, diffraction_order_candidate(span, c), r),
                                                 wanted, budget).nodes;
  }
  vec3 xyz = vec3(0.0);
  int c = -1, i = 0;
  ivec2 j = span.lo;
  DiffractionOrderInterval I = DiffractionOrderInterval(0.0, 0.0, 0);
  for (int t = 0; t < total; ++t, ++i) {
    while (i >= I.nodes && c + 1 < candidates) {  // the next order with nodes (the guard: c stays a candidate)
      j = diffraction_order_candidate(span, ++c);
      I = diffraction_order_interval_within(diffraction_order_interval(L, uv, j, r), wanted, budget);
      i = 0;
    }
    float lambda = diffraction_order_lambda(I, i);
    DiffractionObserverLookup look = diffraction_observer_lookup(lambda, o.lambda0_nm, o.entries);
    if (!look.valid) continue;
    vec3 observer = mix(diffraction_observer_at(o.first + uint(look.index)).xyz,
                        diffraction_observer_at(o.first + uint(look.index) + 1u).xyz, look.f);
    // over the pixel, the order's own bin weighed by its window's mean; at the centre, the window sum by the share
    float weight = over_pixel ? diffraction_window_over_pixel(L, uv, steps, j, 2.0 * FACET_PI / lambda)
                              : diffraction_order_share(L, uv, lambda, j);
    float weighed =
        diffraction_window_value(info, first_coefficient, wi, wr, lambda, L.repeats, over_pixel, j * L.repeats).brdf *
        weight;
    xyz += (weighed * I.step) * observer;
  }
  return xyz;
}

#endif
