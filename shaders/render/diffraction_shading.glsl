// The diffracted light of "diffraction" materials in the direct pass (docs/diffraction.md,
// "Rendering") and docs/diffraction_fast_paths.md: the FACET_RENDER_BINDING_DIFFRACTION_* slots of
// layout/render_layout.glsl (render/diffraction_bindings.glsl), compiled in only when kHasDiffraction is set.
// The per-pixel geometry (the grating frame, wi and wr in it) is computed once; then one switch on
// kDiffractionMethod picks how the spectrum becomes a colour:
//   0 spectral   sum over the material's wavelength samples of the Taylor BRDF times their XYZ weights
//   1 preintegrated  the material's wavelength-integrated tables (diffraction_preintegrated_*), a polynomial in w
//   2 orders     the Taylor BRDF at the wavelengths near the grating's orders (diffraction_observer);
//                spectral where the host found restricting not worth it (not periodic, or orders unresolved: F.10, F.11)
//                and compiled the spectral path in (gpu::direct_pass_code: a scene whose orders are all restricted
//                gets a variant without it)
// The includer declares kHasDiffraction and kDiffractionMethod before including this file; a variant
// of the pass compiles in only the methods it covers (render/variant_code.glsl): `preintegrated` alone
// leaves the spectral path out, which `orders` keeps for its fallback where some material needs it.
#ifndef FACET_RENDER_DIFFRACTION_SHADING_GLSL
#define FACET_RENDER_DIFFRACTION_SHADING_GLSL
#include "layout/diffraction_layout.glsl"
#include "lib/diffraction_frame.glsl"
#include "render/diffraction_bindings.glsl"

#include "render/diffraction_orders.glsl"
#include "render/diffraction_preintegrated.glsl"
#include "render/diffraction_taylor.glsl"
#include "render/variant_code.glsl"

const uint kDiffractionSpectral = 0u;
const uint kDiffractionPreintegrated = 1u;
const uint kDiffractionOrders = 2u;

#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_SPECTRAL)
// sum_i BRDF(lambda_i) xyz_weight_i over the material's wavelength samples.
vec3 diffraction_spectral_xyz(GpuDiffractionMaterial m, vec3 wi, vec3 wr) {
  vec3 xyz = vec3(0.0);
  for (uint i = m.offsets.y; i < m.offsets.y + m.offsets.z; ++i) {
    vec4 sample_i = diffraction_wavelength_at(i);
    xyz += diffraction_taylor_value(m.table, m.offsets.x, wi, wr, sample_i.x, ivec2(1, 1)).brdf * sample_i.yzw;
  }
  return xyz;
}
#endif

// Radiance diffracted toward v by diffraction material `index` at a point with shading normal n (facing
// the viewer; `below`: turned from the surface's own, diffraction_directions_seen) and tangent dpdu, lit from
// l with the light's visibility. over_pixel (a constant of the call site): `orders` takes the mean over the
// pixel whose (u, v) moves by pixel_steps per pixel step (eqs. O1-O3 of docs/diffraction_fast_paths.md); the
// other methods take the colour at the pixel's centre.
vec3 diffraction_shading(uint index, vec3 n, bool below, vec3 dpdu, vec3 v, vec3 l, float visibility,
                         bool over_pixel, vec4 pixel_steps) {
  DiffractionDirections d = diffraction_directions_seen(n, dpdu, l, v, below);
  if (!d.lit || visibility == 0.0) return vec3(0.0);
  GpuDiffractionMaterial m = diffraction_material_at(index);
  vec3 rgb = vec3(0.0);
  switch (kDiffractionMethod) {
#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_PREINTEGRATED)
    case kDiffractionPreintegrated:
      rgb = diffraction_preintegrated_rgb(
          PreintegratedSource(PreintegratedGrid(m.preintegrated_grid.xy, m.preintegrated_grid.zw, m.preintegrated_shape.x,
                                                m.preintegrated_shape.y, m.preintegrated_shape.z, m.preintegrated_shape.w),
                              m.fast_offsets.x, m.fast_offsets.y, m.preintegrated_scalars.x, m.preintegrated_scalars.y,
                              m.preintegrated_scalars.z, m.preintegrated_scalars.w, m.fast_scalars.x),
          d.wi, d.wr);
      break;
#endif
#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_ORDERS)
    case kDiffractionOrders:
      // A variant without the spectral path renders only scenes whose every material's orders are restricted.
      if (m.fast_scalars.z != 0.0 || !FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_SPECTRAL)) {
        DiffractionOrderLattice lattice = DiffractionOrderLattice(m.order_lattice0.xy, m.order_lattice0.z, m.order_lattice0.w,
                                                                  m.order_lattice1.x, m.order_lattice1.y,
                                                                  m.order_lattice1.z, m.order_lattice1.w,
                                                                  m.order_repeats.xy, m.fast_scalars.w, m.order_repeats.z);
        OrderObserver observer = OrderObserver(m.fast_offsets.z, int(m.fast_offsets.w), m.fast_scalars.y);
        rgb = spectral_xyz_to_linear_srgb(
            diffraction_orders_xyz(lattice, m.table, m.offsets.x, observer, d.wi, d.wr, over_pixel, pixel_steps));
        break;
      }
      // Not restricted: on to the spectral path, one call site of it for both methods (each call site of
      // an inlined function is compiled on its own).
#endif
#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_SPECTRAL)
    case kDiffractionSpectral:
    default:
      rgb = spectral_xyz_to_linear_srgb(diffraction_spectral_xyz(m, d.wi, d.wr));
      break;
#endif
  }
  return diffraction_radiance_rgb(rgb, d.wi.z, globals.light_irradiance.rgb, visibility);
}

#endif
