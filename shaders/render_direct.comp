#version 450
#extension GL_GOOGLE_include_directive : require
// One primary ray per pixel through the scene's planes, spheres and BVH of triangles; direct
// lighting (Lambert or microflake half-space) with a shadow ray toward the directional light.
// Specialization constant 0 compiles the microflake branch in only for scenes that use it.
#include "layout/scene_layout.glsl"
#include "lib/analytic_intersect.glsl"
#include "lib/camera.glsl"
#include "lib/lambert.glsl"
#include "lib/microflake_shading.glsl"
#include "lib/triangle_intersect.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const bool kHasMicroflake = false;

layout(std430, binding = 0) readonly buffer Globals { GpuGlobals globals; };
layout(std430, binding = 1) readonly buffer Planes { GpuPlane planes[]; };
layout(std430, binding = 2) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = 3) readonly buffer Nodes { GpuBvhNode nodes[]; };
layout(std430, binding = 4) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = 5) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 6) writeonly buffer Pixels { vec4 pixels[]; };  // this tile's pixels, row-major
layout(push_constant) uniform Push { GpuTile tile; };

const float kInfinity = 1e30;
const uint kNoHit = 0xffffffffu;
const int kStackSize = 64;

struct Hit {
  float t;
  vec3 normal;  // unnormalised shading normal (any side)
  uint material;
};

// Nearest triangle hit below hit.t through the BVH (stack-based, near child first).
Hit trace_triangles(vec3 o, vec3 d, Hit hit) {
  if (globals.counts.z == 0u) return hit;
  vec3 inv_d = 1.0 / d;
  uint stack[kStackSize];
  int top = 0;
  stack[top++] = 0u;
  while (top > 0) {
    GpuBvhNode node = nodes[stack[--top]];
    if (intersect_box(o, inv_d, node.lo, node.hi, hit.t) < 0.0) continue;
    if (node.count > 0u) {
      for (uint i = node.left_or_first; i < node.left_or_first + node.count; ++i) {
        GpuTriangle tri = triangles[i];
        vec3 tb = intersect_triangle(o, d, tri.p0.xyz, tri.p1.xyz, tri.p2.xyz, 0.0, hit.t);
        if (tb.x < 0.0) continue;
        vec3 n = (1.0 - tb.y - tb.z) * tri.n0.xyz + tb.y * tri.n1.xyz + tb.z * tri.n2.xyz;
        if (dot(n, n) == 0.0) n = cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz);
        hit = Hit(tb.x, n, tri.material.x);
      }
    } else if (top + 2 <= kStackSize) {
      stack[top++] = node.left_or_first + 1u;
      stack[top++] = node.left_or_first;
    }
  }
  return hit;
}

Hit trace(vec3 o, vec3 d, float t_min, float t_max) {
  Hit hit = Hit(t_max, vec3(0.0), kNoHit);
  for (uint i = 0u; i < globals.counts.x; ++i) {
    float t = intersect_plane(o, d, planes[i].point.xyz, planes[i].normal.xyz, t_min, hit.t);
    if (t > 0.0) hit = Hit(t, planes[i].normal.xyz, planes[i].material.x);
  }
  for (uint i = 0u; i < globals.counts.y; ++i) {
    vec4 s = spheres[i].center_radius;
    float t = intersect_sphere(o, d, s.xyz, s.w, t_min, hit.t);
    if (t > 0.0) hit = Hit(t, o + t * d - s.xyz, spheres[i].material.x);
  }
  return trace_triangles(o, d, hit);
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy + tile.rect.xy;
  if (gl_GlobalInvocationID.x >= tile.rect.z || gl_GlobalInvocationID.y >= tile.rect.w) return;
  vec2 resolution = vec2(globals.image.xy);
  vec3 o = globals.camera_origin.xyz;
  vec3 d = camera_ray_direction(globals.camera_forward.xyz, globals.camera_right.xyz,
                                globals.camera_up.xyz, vec2(pixel) + 0.5, resolution);
  Hit hit = trace(o, d, 0.0, kInfinity);
  vec3 color = globals.background.rgb;
  if (hit.material != kNoHit) {
    vec3 p = o + hit.t * d;
    vec3 n = normalize(hit.normal);
    if (dot(n, d) > 0.0) n = -n;
    vec3 l = globals.light_direction.xyz;
    // Offset the shadow ray's origin by a distance relative to the scene's scale at p.
    vec3 shadow_origin = p + n * (1e-4 * max(1.0, length(p)));
    float visibility = dot(n, l) > 0.0 && trace(shadow_origin, l, 0.0, kInfinity).material != kNoHit ? 0.0 : 1.0;
    GpuMaterial m = materials[hit.material];
    if (kHasMicroflake && m.kind.x == FACET_MATERIAL_MICROFLAKE)
      color = microflake_radiance(int(m.kind.y), m.params.x, m.albedo.rgb, n, -d, l, globals.light_irradiance.rgb,
                                  visibility, globals.ambient.rgb);
    else
      color = lambert_radiance(m.albedo.rgb, n, l, globals.light_irradiance.rgb, visibility, globals.ambient.rgb);
  }
  pixels[gl_GlobalInvocationID.y * tile.rect.z + gl_GlobalInvocationID.x] = vec4(color, 1.0);
}
