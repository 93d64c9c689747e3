// A hit on a microsurface's traced height field (render/heightfield_trace.glsl), as each method that
// traces shades it (docs/microsurface_filtering.md, "Traced height fields"). Included after
// render/trace.glsl, whose Hit it builds the flat rectangle's shadow ray from.
#ifndef FACET_RENDER_MICROSURFACE_FIELD_GLSL
#define FACET_RENDER_MICROSURFACE_FIELD_GLSL
#include "render/microsurface_shading.glsl"
#include "render/microsurface_statistics_queue.glsl"
#include "render/trace.glsl"
#include "render/variant_code.glsl"

// Where a field hit is shaded from: the pixel's footprint around it and the weight w of its traced
// shading (1 but for filtered, which blends toward the statistics from two texels on, (T1)).
struct MicrosurfaceFieldSample {
  MicrosurfaceFootprint fp;
  float w;
};

MicrosurfaceFieldSample microsurface_field_sample(GpuMaterial m, Hit hit, vec3 o, vec3 d, vec3 p, vec3 d_dx,
                                                  vec3 d_dy) {
  GpuPlane plane = plane_at(hit.index);
  MicrosurfaceFootprint fp = microsurface_footprint(m, plane, o, d, p, d_dx, d_dy, plane.normal.xyz);
#if FACET_VARIANT_HAS(FACET_CODE_FILTERED)
  if (kTextureMethod >= 3u) fp = microsurface_footprint_on_surface(m, plane, o, d, p, d_dx, d_dy, fp);
#endif
  return MicrosurfaceFieldSample(fp, kTextureMethod >= 3u ? microsurface_trace_weight(fp) : 1.0);
}

// The hit as the flat rectangle's, its normal facing the ray d: where filtered's statistics' shadow ray
// starts, offset along that normal (above the field, a graph over the rectangle). It meets the other
// objects and the field beyond the footprint: Smith models the shadows of the detail inside the
// footprint, the ray those the surface beyond it casts (docs/microsurface_filtering.md, "Shadows").
Hit microsurface_flat_hit(Hit hit, vec3 d) {
  vec3 normal = plane_at(hit.index).normal.xyz;
  return Hit(hit.t, dot(normal, d) > 0.0 ? -normal : normal, hit.material, kPlane, hit.index, vec2(0.0));
}

// naive (ss:K): the hit as the reference shades a sample, its light through every field (a field
// shadows itself) and the other objects: visibility.x, which the caller traces when s.w > 0.
// filtered: the same where the footprint is within a texel; from two texels on the footprint's
// statistics around the traced hit, lit by visibility.y, the ray through the field beyond the footprint; a blend
// between (T1), whose statistics' part is left to the queue (pending_statistics). n: the hit's micro-normal
// facing the viewer.
vec3 microsurface_field_radiance(GpuMaterial m, Hit hit, MicrosurfaceFieldSample s, vec3 d, vec3 n, vec3 l,
                                 vec2 visibility) {
  GpuPlane plane = plane_at(hit.index);
  vec3 c = vec3(0.0);
  if (s.w > 0.0)
    c += s.w * microsurface_traced_radiance(m, plane, hit.barycentric, n, -d, l, visibility.x, -normalize(s.fp.d_dx),
                                            -normalize(s.fp.d_dy), s.fp.duv_dx * s.fp.size, s.fp.duv_dy * s.fp.size);
#if FACET_VARIANT_HAS(FACET_CODE_FILTERED)  // naive: s.w = 1
  // The statistics' part, microsurface_field_statistics, is added by the statistics' dispatch
  // (render/microsurface_statistics_queue.glsl).
  if (s.w < 1.0) {
    statistics_pending = true;
    pending_statistics = QueuedStatistics(0u, hit.t, hit.index, visibility.y);
  }
#endif
  return c;
}

#if FACET_VARIANT_HAS(FACET_CODE_FILTERED)
// The statistics' part of a field hit's radiance, which microsurface_field_radiance leaves to the queue.
vec3 microsurface_field_statistics(GpuMaterial m, Hit hit, MicrosurfaceFieldSample s, vec3 d, vec3 l, float visibility) {
  return (1.0 - s.w) * microsurface_radiance(m, plane_at(hit.index), s.fp, d, l, visibility, true);
}
#endif

#endif
