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
vec3 diffraction_orders_xyz(DiffractionOrderLattice L, DiffractionTableInfo info, uint first_coefficient,
                            OrderObserver o, vec3 wi, vec3 wr) {
  vec2 uv = -(wi.xy + wr.xy);
  DiffractionOrderSpan span = diffraction_order_span(L, uv);
  int candidates = diffraction_order_candidates(span);
  int total = 0;
  for (int c = 0; c < candidates; ++c)
    total += diffraction_order_interval(L, uv, diffraction_order_candidate(span, c)).nodes;
  vec3 xyz = vec3(0.0);
  int c = -1, i = 0;
  ivec2 j = span.lo;
  DiffractionOrderInterval I = DiffractionOrderInterval(0.0, 0.0, 0);
  for (int t = 0; t < total; ++t, ++i) {
    while (i >= I.nodes && c + 1 < candidates) {  // the next order with nodes (the guard: c stays a candidate)
      j = diffraction_order_candidate(span, ++c);
      I = diffraction_order_interval(L, uv, j);
      i = 0;
    }
    float lambda = diffraction_order_lambda(I, i);
    DiffractionObserverLookup look = diffraction_observer_lookup(lambda, o.lambda0_nm, o.entries);
    if (!look.valid) continue;
    vec3 observer = mix(diffraction_observer_at(o.first + uint(look.index)).xyz,
                        diffraction_observer_at(o.first + uint(look.index) + 1u).xyz, look.f);
    float brdf = diffraction_taylor_value(info, first_coefficient, wi, wr, lambda, L.repeats).brdf;
    xyz += (brdf * diffraction_order_share(L, uv, lambda, j) * I.step) * observer;
  }
  return xyz;
}

#endif
