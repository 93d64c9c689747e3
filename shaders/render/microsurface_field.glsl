// A hit on a microsurface's traced height field (render/heightfield_trace.glsl), as each method that
// traces shades it (docs/microsurface_filtering.md, "Traced height fields"). Included after
// render/trace.glsl, whose shadow rays it casts.
#ifndef FACET_RENDER_MICROSURFACE_FIELD_GLSL
#define FACET_RENDER_MICROSURFACE_FIELD_GLSL
#include "render/microsurface_shading.glsl"
#include "render/trace.glsl"

// naive (ss:K): the hit as the reference shades a sample, its light through every field (a field
// shadows itself) and the other objects. filtered: the same where the footprint is within a texel;
// from two texels on the footprint's statistics around the traced hit, which model the shadows of the
// detail inside it (Smith), so their light is only tested against the other objects; a blend between
// (T1). p: the hit, n: its micro-normal facing the viewer, d_dx, d_dy: the neighbouring pixels' rays.
vec3 microsurface_field_radiance(GpuMaterial m, Hit hit, vec3 o, vec3 d, vec3 p, vec3 n, vec3 d_dx, vec3 d_dy, vec3 l) {
  GpuPlane plane = plane_at(hit.index);
  MicrosurfaceFootprint fp = microsurface_footprint(m, plane, o, d, p, d_dx, d_dy, plane.normal.xyz);
  if (kTextureMethod >= 3u) fp = microsurface_footprint_on_surface(m, plane, o, d, p, d_dx, d_dy, fp);
  float w = kTextureMethod >= 3u ? microsurface_trace_weight(fp) : 1.0;
  vec3 c = vec3(0.0);
  if (w > 0.0) {
    // Hits are exact to a few float ulps, and the field's detail is finer than the macro-surfaces' offset.
    float visibility = dot(n, l) > 0.0 && occluded(p + n * (1e-5 * max(1.0, length(p))), l, hit, n, true) ? 0.0 : 1.0;
    c += w * microsurface_traced_radiance(m, plane, hit.barycentric, n, -d, l, visibility);
  }
  if (w < 1.0) {
    vec3 flat_n = dot(plane.normal.xyz, d) > 0.0 ? -plane.normal.xyz : plane.normal.xyz;
    Hit flat_hit = Hit(hit.t, flat_n, hit.material, kPlane, hit.index, vec2(0.0));
    float visibility = dot(flat_n, l) > 0.0 && occluded(p + flat_n * (1e-4 * max(1.0, length(p))), l, flat_hit, flat_n, false) ? 0.0 : 1.0;
    c += (1.0 - w) * microsurface_radiance(m, plane, fp, d, l, visibility, true);
  }
  return c;
}

#endif
