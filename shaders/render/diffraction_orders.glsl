// The order-restricted colour (lib/diffraction_orders.glsl; the C++ twin is evaluate_orders in
// renderer/diffraction/order_wavelengths.cpp): the per-wavelength Taylor BRDF
// (render/diffraction_taylor.glsl) at the nodes of each reaching order's interval, weighted by the
// order's share, the node's step and the observer. The includer declares
// `vec2 diffraction_coefficients[]` and `vec4 diffraction_observer[]` (XYZ per nm, xyz_density).
// Gratings that are not periodic never reach this path (the host picks the spectral one).
#ifndef FACET_RENDER_DIFFRACTION_ORDERS_GLSL
#define FACET_RENDER_DIFFRACTION_ORDERS_GLSL
#include "lib/diffraction_orders.glsl"
#include "lib/spectral_srgb.glsl"
#include "render/diffraction_taylor.glsl"

struct OrderObserver {
  uint first;     // of the material's table in diffraction_observer
  int entries;    // 1 nm entries from lambda0
  float lambda0_nm;
};

vec3 diffraction_orders_xyz(DiffractionOrderLattice L, DiffractionTableInfo info, uint first_coefficient,
                            OrderObserver o, vec3 wi, vec3 wr) {
  vec2 uv = -(wi.xy + wr.xy);
  DiffractionOrderSpan span = diffraction_order_span(L, uv);
  vec3 xyz = vec3(0.0);
  for (int jy = span.lo.y; jy <= span.hi.y; ++jy) {
    for (int jx = span.lo.x; jx <= span.hi.x; ++jx) {
      ivec2 j = ivec2(jx, jy);
      DiffractionOrderInterval I = diffraction_order_interval(L, uv, j);
      for (int i = 0; i < I.nodes; ++i) {
        float lambda = diffraction_order_lambda(I, i);
        DiffractionObserverLookup look = diffraction_observer_lookup(lambda, o.lambda0_nm, o.entries);
        if (!look.valid) continue;
        vec3 observer = mix(diffraction_observer[o.first + uint(look.index)].xyz,
                            diffraction_observer[o.first + uint(look.index) + 1u].xyz, look.f);
        float brdf = diffraction_taylor_value(info, first_coefficient, wi, wr, lambda).brdf;
        xyz += (brdf * diffraction_order_share(L, uv, lambda, j) * I.step) * observer;
      }
    }
  }
  return xyz;
}

#endif
