// Closest hits of rays against the scene's planes, spheres and BVH of triangles, any hit for shadow
// rays, and the surface parameterisation (uv, dp/du, dp/dv) at a hit: what every material's shading
// starts from. The including shader declares the specialization constants kHasSpheres and
// kHasTriangles (false: the scene has none, and their loops are compiled out), kPlaneTrips and
// kSphereTrips (below) and kHasMicrosurface.
// With `fields`, microsurface planes are their height fields (render/heightfield_trace.glsl), else
// flat rectangles.
#ifndef FACET_RENDER_TRACE_GLSL
#define FACET_RENDER_TRACE_GLSL
#include "lib/analytic_intersect.glsl"
#include "lib/triangle_intersect.glsl"
#ifdef FACET_HEIGHT_FIELDS
#include "render/heightfield_trace.glsl"
#endif
#include "render/scene_bindings.glsl"
#include "render/variant_code.glsl"

const float kInfinity = 1e30;
const uint kNoHit = 0xffffffffu;
const int kStackSize = 64;
const uint kPlane = 0u;
const uint kSphere = 1u;
const uint kTriangle = 2u;
const uint kHeightField = 3u;  // index: the plane; barycentric: the hit in field texels

struct Hit {
  float t;
  vec3 normal;  // unnormalised shading normal (any side)
  uint material;
  uint primitive;  // kPlane, kSphere, kTriangle
  uint index;
  vec2 barycentric;  // triangles; height fields: the hit's texel coordinates
};

#ifdef FACET_HEIGHT_FIELDS
bool is_height_field(GpuPlane plane, bool fields) {
  return kHasMicrosurface && fields && material_at(plane.material.x).kind.x == FACET_MATERIAL_MICROSURFACE;
}

// The first hit of o + t d, t in (0, t_max), with the height field of microsurface plane i, or -1.
float trace_height_field(uint i, vec3 o, vec3 d, float t_max, out vec2 q) {
  GpuPlane plane = plane_at(i);
  GpuMaterial m = material_at(plane.material.x);
  HeightFieldRay r = heightfield_ray(m, plane, o, d, t_max);
  float t = heightfield_search(heightfield_of(m, plane), r);
  q = clamp(r.o.xy + t * r.d.xy, vec2(0.0), 2.0 * plane.uv_half_size.zw / m.albedo.w);
  return t;
}
#endif

// The trips of the loops over planes and spheres: the scene's count where it has few, a constant, so the
// loops are unrolled (lavapipe pays a loop's control on every trip, for every lane: docs/render_speed.md,
// "Loops on lavapipe"), else (FACET_RENDER_LOOPED_TRIPS) the count the scene's globals hold.
uint plane_trips() { return kPlaneTrips != FACET_RENDER_LOOPED_TRIPS ? kPlaneTrips : globals.counts.x; }
uint sphere_trips() { return kSphereTrips != FACET_RENDER_LOOPED_TRIPS ? kSphereTrips : globals.counts.y; }

// The closest hit before hit.t, or with `any_hit` the first one found in traversal order (shadow
// rays need only whether one exists; callers pass a constant, so each use compiles to one variant).
Hit trace_triangles(vec3 o, vec3 d, Hit hit, bool any_hit) {
#if FACET_VARIANT_HAS(FACET_CODE_TRIANGLES)
  if (!kHasTriangles || globals.counts.z == 0u) return hit;
  vec3 inv_d = 1.0 / d;
  uint stack[kStackSize];
  int top = 0;
  stack[top++] = 0u;
  while (top > 0) {
    GpuBvhNode node = node_at(stack[--top]);
    if (intersect_box(o, inv_d, node.lo, node.hi, hit.t) < 0.0) continue;
    if (node.count > 0u) {
      for (uint i = node.left_or_first; i < node.left_or_first + node.count; ++i) {
        GpuTriangle tri = triangle_at(i);
        vec3 tb = intersect_triangle(o, d, tri.p0.xyz, tri.p1.xyz, tri.p2.xyz, 0.0, hit.t);
        if (tb.x < 0.0) continue;
        vec3 n = (1.0 - tb.y - tb.z) * tri.n0.xyz + tb.y * tri.n1.xyz + tb.z * tri.n2.xyz;
        if (dot(n, n) == 0.0) n = cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz);
        hit = Hit(tb.x, n, tri.material.x, kTriangle, i, tb.yz);
        if (any_hit) return hit;
      }
    } else if (top + 2 <= kStackSize) {
      stack[top++] = node.left_or_first + 1u;
      stack[top++] = node.left_or_first;
    }
  }
#endif
  return hit;
}

bool inside_plane_rectangle(GpuPlane plane, vec3 p) {
  if (plane.uv_half_size.z <= 0.0) return true;
  vec3 r = p - plane.point.xyz;
  vec3 bitangent = cross(plane.normal.xyz, plane.tangent.xyz);
  return abs(dot(r, plane.tangent.xyz)) <= plane.uv_half_size.z && abs(dot(r, bitangent)) <= plane.uv_half_size.w;
}

Hit trace(vec3 o, vec3 d, float t_min, float t_max, bool fields) {
  Hit hit = Hit(t_max, vec3(0.0), kNoHit, 0u, 0u, vec2(0.0));
  [[unroll]] for (uint i = 0u; i < plane_trips(); ++i) {
    GpuPlane plane = plane_at(i);
#ifdef FACET_HEIGHT_FIELDS
    if (is_height_field(plane, fields)) {
      vec2 q;
      GpuMaterial m = material_at(plane.material.x);
      float t = trace_height_field(i, o, d, hit.t, q);
      if (t > t_min) {
        hit = Hit(t, heightfield_normal(plane, heightfield_point(heightfield_quads(m), q, m.albedo.w)), plane.material.x,
                  kHeightField, i, q);
      }
      continue;
    }
#endif
    float t = intersect_plane(o, d, plane.point.xyz, plane.normal.xyz, t_min, hit.t);
    if (t > 0.0 && inside_plane_rectangle(plane, o + t * d))
      hit = Hit(t, plane.normal.xyz, plane.material.x, kPlane, i, vec2(0.0));
  }
#if FACET_VARIANT_HAS(FACET_CODE_SPHERES)
  [[unroll]] for (uint i = 0u; kHasSpheres && i < sphere_trips(); ++i) {
    GpuSphere sphere = sphere_at(i);
    vec4 s = sphere.center_radius;
    float t = intersect_sphere(o, d, s.xyz, s.w, t_min, hit.t);
    if (t > 0.0) hit = Hit(t, o + t * d - s.xyz, sphere.material.x, kSphere, i, vec2(0.0));
  }
#endif
  return trace_triangles(o, d, hit, false);
}

// Whether anything lies on the shadow ray o + t l, t in (0, inf), leaving the surface at `from`
// (offset from it along the shading normal n facing the ray's side, with dot(n, l) > 0). The search
// stops at the first occluder. Two primitives are skipped because they provably cannot block it: the
// plane `from` lies on (the ray leaves it and never returns), and `from`'s sphere when the ray leaves
// its outside (a convex body lies entirely behind its tangent plane; from inside, n points inwards
// and the far wall does block). With `fields`, microsurfaces' height fields are traced from field_skip
// along the ray on (the other objects from o).
bool occluded(vec3 o, vec3 l, Hit from, vec3 n, bool fields, float field_skip) {
  uint skip_plane = from.primitive == kPlane ? from.index : kNoHit;
  uint skip_sphere = from.primitive == kSphere && dot(from.normal, n) > 0.0 ? from.index : kNoHit;
  [[unroll]] for (uint i = 0u; i < plane_trips(); ++i) {
    GpuPlane plane = plane_at(i);
#ifdef FACET_HEIGHT_FIELDS
    if (is_height_field(plane, fields)) {  // a field shadows itself: never skipped
      vec2 q;
      if (trace_height_field(i, o + field_skip * l, l, kInfinity, q) > 0.0) return true;
      continue;
    }
#endif
    if (i == skip_plane) continue;
    float t = intersect_plane(o, l, plane.point.xyz, plane.normal.xyz, 0.0, kInfinity);
    if (t > 0.0 && inside_plane_rectangle(plane, o + t * l)) return true;
  }
#if FACET_VARIANT_HAS(FACET_CODE_SPHERES)
  [[unroll]] for (uint i = 0u; kHasSpheres && i < sphere_trips(); ++i) {
    vec4 s = sphere_at(i).center_radius;
    if (i != skip_sphere && intersect_sphere(o, l, s.xyz, s.w, 0.0, kInfinity) > 0.0) return true;
  }
#endif
  return trace_triangles(o, l, Hit(kInfinity, vec3(0.0), kNoHit, 0u, 0u, vec2(0.0)), true).material != kNoHit;
}

// What the hit's primitive shows the neighbouring camera ray o + t d_n, to first order for a triangle: a point
// and the (unnormalised, any side) shading normal there. A plane's normal is its own; a sphere's is exact where
// the ray meets it and, where it passes it, the normal at its closest approach (the silhouette's, perpendicular
// to the ray: the pixel's normals end there); a triangle's interpolates its vertex normals at the barycentrics
// of the ray's crossing of the tangent plane at the hit p (a flat one's is its face normal); the point is where
// the ray meets the tangent plane (a sphere: the point of that normal). Used by the filtered microflake lobe
// (microflake_pixel_lobe.glsl) and the diffraction orders over the pixel (diffraction_pixel_uv_steps,
// render/direct_pass.glsl).
struct SurfaceSeenBy {
  vec3 p;
  vec3 n;
};

SurfaceSeenBy surface_seen_by(Hit hit, vec3 p, vec3 o, vec3 d_n) {
#if FACET_VARIANT_HAS(FACET_CODE_SPHERES)
  if (kHasSpheres && hit.primitive == kSphere) {
    vec4 s = sphere_at(hit.index).center_radius;
    vec3 closest = o + d_n * dot(s.xyz - o, d_n) - s.xyz;  // from the centre to the ray's closest point
    float inside = s.w * s.w - dot(closest, closest);
    vec3 normal = inside > 0.0 ? closest - d_n * sqrt(inside) : closest;
    return SurfaceSeenBy(s.xyz + normal, normal);
  }
#endif
  vec3 n = hit.normal;
  vec3 q = o + d_n * (dot(p - o, n) / (abs(dot(d_n, n)) > 1e-8 ? dot(d_n, n) : 1e-8));  // on the tangent plane
#if FACET_VARIANT_HAS(FACET_CODE_TRIANGLES)
  if (kHasTriangles && hit.primitive == kTriangle) {
    GpuTriangle tri = triangle_at(hit.index);
    vec3 e1 = tri.p1.xyz - tri.p0.xyz, e2 = tri.p2.xyz - tri.p0.xyz, r = q - tri.p0.xyz;
    float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), r1 = dot(r, e1), r2 = dot(r, e2);
    vec2 b = vec2(d22 * r1 - d12 * r2, d11 * r2 - d12 * r1) / max(d11 * d22 - d12 * d12, 1e-30);
    vec3 interpolated = (1.0 - b.x - b.y) * tri.n0.xyz + b.x * tri.n1.xyz + b.y * tri.n2.xyz;
    return SurfaceSeenBy(q, dot(tri.n0.xyz, tri.n0.xyz) == 0.0 ? n : interpolated);
  }
#endif
  return SurfaceSeenBy(q, n);
}

// The hit's unit shading normal turned to the side the ray d comes from, as renderer/cpu/ray_caster.cpp's
// face_toward_ray turns it: to the side of the surface's geometric normal that faces the ray. For a plane, a
// sphere or a field that is the shading normal itself; a triangle's interpolated vertex normal can lean away
// from the ray near a smooth mesh's silhouette while its face is seen from the front, and turning it by the ray
// alone shaded such hits as the mesh's other side (default.json's torus: a band 8 % too dark at its far rim).
// `back_face`: the surface is seen from behind its normal (a grating seen from below, eq. R1).
struct FacingNormal {
  vec3 n;
  bool back_face;
};

FacingNormal facing_normal(Hit hit, vec3 d) {
  vec3 n = normalize(hit.normal);
  bool back_face = dot(n, d) > 0.0;
#if FACET_VARIANT_HAS(FACET_CODE_TRIANGLES)
  if (kHasTriangles && hit.primitive == kTriangle) {
    GpuTriangle tri = triangle_at(hit.index);
    vec3 face = cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz);
    float toward = dot(n, face);
    back_face = dot(face, d) > 0.0 ? toward > 0.0 : toward < 0.0;
  }
#endif
  return FacingNormal(back_face ? -n : n, back_face);
}

// uv at p and the tangents dp/du, dp/dv (the conventions of renderer/cpu/ray_caster.cpp).
struct SurfaceUv {
  vec2 uv;
  vec3 dpdu;
  vec3 dpdv;
};

SurfaceUv surface_uv(Hit hit, vec3 p) {
  if (hit.primitive == kPlane) {
    GpuPlane plane = plane_at(hit.index);
    vec3 bitangent = cross(plane.normal.xyz, plane.tangent.xyz);
    vec3 r = p - plane.point.xyz;
    vec2 scale = plane.uv_half_size.xy;
    return SurfaceUv(vec2(dot(r, plane.tangent.xyz), dot(r, bitangent)) * scale, plane.tangent.xyz / scale.x,
                     bitangent / scale.y);
  }
  // lavapipe runs every branch for every pixel: absent primitive kinds are compiled out here too.
#if FACET_VARIANT_HAS(FACET_CODE_SPHERES)
  if (kHasSpheres && hit.primitive == kSphere) {
    // u: longitude about +y from +z, v: polar angle from +y (both in [0, 1]).
    vec4 s = sphere_at(hit.index).center_radius;
    vec3 n = normalize(p - s.xyz);
    float phi = atan(n.x, n.z);
    float theta = acos(clamp(n.y, -1.0, 1.0));
    vec3 dpdu = 2.0 * FACET_PI * s.w * vec3(n.z, 0.0, -n.x);
    vec3 dpdv = FACET_PI * s.w * vec3(cos(theta) * sin(phi), -sin(theta), cos(theta) * cos(phi));
    return SurfaceUv(vec2(0.5 + phi * (0.5 * FACET_INV_PI), theta * FACET_INV_PI), dpdu, dpdv);
  }
#endif
#if !FACET_VARIANT_HAS(FACET_CODE_TRIANGLES)
  return SurfaceUv(vec2(0.0), vec3(0.0), vec3(0.0));  // not reached: hits are planes or spheres
#else
  if (!kHasTriangles) return SurfaceUv(vec2(0.0), vec3(0.0), vec3(0.0));  // not reached: hits are planes or spheres
  GpuTriangle tri = triangle_at(hit.index);
  vec2 b = hit.barycentric;
  vec2 uv0 = tri.uv01.xy, uv1 = tri.uv01.zw, uv2 = tri.uv2.xy;
  vec2 uv = (1.0 - b.x - b.y) * uv0 + b.x * uv1 + b.y * uv2;
  // dp = e1 db1 + e2 db2 and duv = duv1 db1 + duv2 db2: invert the uv Jacobian of the triangle.
  vec3 e1 = tri.p1.xyz - tri.p0.xyz, e2 = tri.p2.xyz - tri.p0.xyz;
  vec2 duv1 = uv1 - uv0, duv2 = uv2 - uv0;
  float det = duv1.x * duv2.y - duv1.y * duv2.x;
  if (abs(det) < 1e-20) return SurfaceUv(uv, vec3(0.0), vec3(0.0));
  return SurfaceUv(uv, (duv2.y * e1 - duv1.y * e2) / det, (duv1.x * e2 - duv2.x * e1) / det);
#endif
}

#endif
