#version 450
#extension GL_GOOGLE_include_directive : require
// Primary rays through the scene's planes, spheres and BVH of triangles; direct lighting from the
// directional light (with a shadow ray) plus the ambient fill, for every macro-surface material.
// Specialization constants compile in only what a scene and a method use:
//   0 kHasMicroflake   microflake half-spaces (lib/microflake_shading.glsl)
//   1 kHasTexture      colour-mapped textures
//   2 kTextureMethod   0 naive (finest level, colour map per sample), 1 mip (MIP-mapped texture, then
//                      colour map), 2 colormip (MIP-mapped colour-mapped texture), 3 filtered (the
//                      footprint's Gaussian N(mu, sigma^2) integrated against the colour map exactly)
//   3 kSamplesPerAxis  K: K x K stratified rays per pixel, averaged (ss:K)
#include "layout/scene_layout.glsl"
#include "lib/analytic_intersect.glsl"
#include "lib/camera.glsl"
#include "lib/colormap_filter.glsl"
#include "lib/lambert.glsl"
#include "lib/microflake_shading.glsl"
#include "lib/texture_footprint.glsl"
#include "lib/triangle_intersect.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const bool kHasMicroflake = false;
layout(constant_id = 1) const bool kHasTexture = false;
layout(constant_id = 2) const uint kTextureMethod = 0u;
layout(constant_id = 3) const uint kSamplesPerAxis = 1u;
const float kMaxAnisotropicTaps = 8.0;

layout(std430, binding = 0) readonly buffer Globals { GpuGlobals globals; };
layout(std430, binding = 1) readonly buffer Planes { GpuPlane planes[]; };
layout(std430, binding = 2) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = 3) readonly buffer Nodes { GpuBvhNode nodes[]; };
layout(std430, binding = 4) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = 5) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 6) writeonly buffer Pixels { vec4 pixels[]; };  // this tile's pixels, row-major
layout(std430, binding = 7) readonly buffer TextureLevels { GpuTextureLevel texture_levels[]; };
layout(std430, binding = 8) readonly buffer Texels { vec4 texels[]; };
layout(std430, binding = 9) readonly buffer Colormaps { GpuColormap colormaps[]; };
layout(std430, binding = 10) readonly buffer ColormapPoints { vec4 colormap_points[]; };  // rgb, position
layout(push_constant) uniform Push { GpuTile tile; };

const float kInfinity = 1e30;
const uint kNoHit = 0xffffffffu;
const int kStackSize = 64;
const uint kPlane = 0u;
const uint kSphere = 1u;
const uint kTriangle = 2u;

struct Hit {
  float t;
  vec3 normal;  // unnormalised shading normal (any side)
  uint material;
  uint primitive;  // kPlane, kSphere, kTriangle
  uint index;
  vec2 barycentric;  // triangles
};

// ---------------------------------------------------------------- tracing

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
        hit = Hit(tb.x, n, tri.material.x, kTriangle, i, tb.yz);
      }
    } else if (top + 2 <= kStackSize) {
      stack[top++] = node.left_or_first + 1u;
      stack[top++] = node.left_or_first;
    }
  }
  return hit;
}

bool inside_plane_rectangle(GpuPlane plane, vec3 p) {
  if (plane.uv_half_size.z <= 0.0) return true;
  vec3 r = p - plane.point.xyz;
  vec3 bitangent = cross(plane.normal.xyz, plane.tangent.xyz);
  return abs(dot(r, plane.tangent.xyz)) <= plane.uv_half_size.z && abs(dot(r, bitangent)) <= plane.uv_half_size.w;
}

Hit trace(vec3 o, vec3 d, float t_min, float t_max) {
  Hit hit = Hit(t_max, vec3(0.0), kNoHit, 0u, 0u, vec2(0.0));
  for (uint i = 0u; i < globals.counts.x; ++i) {
    float t = intersect_plane(o, d, planes[i].point.xyz, planes[i].normal.xyz, t_min, hit.t);
    if (t > 0.0 && inside_plane_rectangle(planes[i], o + t * d))
      hit = Hit(t, planes[i].normal.xyz, planes[i].material.x, kPlane, i, vec2(0.0));
  }
  for (uint i = 0u; i < globals.counts.y; ++i) {
    vec4 s = spheres[i].center_radius;
    float t = intersect_sphere(o, d, s.xyz, s.w, t_min, hit.t);
    if (t > 0.0) hit = Hit(t, o + t * d - s.xyz, spheres[i].material.x, kSphere, i, vec2(0.0));
  }
  return trace_triangles(o, d, hit);
}

// ---------------------------------------------------------------- surface parameterisation

// uv at p and the tangents dp/du, dp/dv (the conventions of renderer/cpu/ray_caster.cpp).
struct SurfaceUv {
  vec2 uv;
  vec3 dpdu;
  vec3 dpdv;
};

SurfaceUv surface_uv(Hit hit, vec3 p) {
  if (hit.primitive == kPlane) {
    GpuPlane plane = planes[hit.index];
    vec3 bitangent = cross(plane.normal.xyz, plane.tangent.xyz);
    vec3 r = p - plane.point.xyz;
    vec2 scale = plane.uv_half_size.xy;
    return SurfaceUv(vec2(dot(r, plane.tangent.xyz), dot(r, bitangent)) * scale, plane.tangent.xyz / scale.x,
                     bitangent / scale.y);
  }
  if (hit.primitive == kSphere) {
    // u: longitude about +y from +z, v: polar angle from +y (both in [0, 1]).
    vec4 s = spheres[hit.index].center_radius;
    vec3 n = normalize(p - s.xyz);
    float phi = atan(n.x, n.z);
    float theta = acos(clamp(n.y, -1.0, 1.0));
    vec3 dpdu = 2.0 * FACET_PI * s.w * vec3(n.z, 0.0, -n.x);
    vec3 dpdv = FACET_PI * s.w * vec3(cos(theta) * sin(phi), -sin(theta), cos(theta) * cos(phi));
    return SurfaceUv(vec2(0.5 + phi * (0.5 * FACET_INV_PI), theta * FACET_INV_PI), dpdu, dpdv);
  }
  GpuTriangle tri = triangles[hit.index];
  vec2 b = hit.barycentric;
  vec2 uv0 = tri.uv01.xy, uv1 = tri.uv01.zw, uv2 = tri.uv2.xy;
  vec2 uv = (1.0 - b.x - b.y) * uv0 + b.x * uv1 + b.y * uv2;
  // dp = e1 db1 + e2 db2 and duv = duv1 db1 + duv2 db2: invert the uv Jacobian of the triangle.
  vec3 e1 = tri.p1.xyz - tri.p0.xyz, e2 = tri.p2.xyz - tri.p0.xyz;
  vec2 duv1 = uv1 - uv0, duv2 = uv2 - uv0;
  float det = duv1.x * duv2.y - duv1.y * duv2.x;
  if (abs(det) < 1e-20) return SurfaceUv(uv, vec3(0.0), vec3(0.0));
  return SurfaceUv(uv, (duv2.y * e1 - duv1.y * e2) / det, (duv1.x * e2 - duv2.x * e1) / det);
}

// ---------------------------------------------------------------- textures and colour maps

// Bilinear between texel centres ((i + 1/2)/W, (j + 1/2)/H), periodic (renderer/cpu/material_shading.cpp).
vec4 sample_level(uint level, vec2 uv) {
  uvec4 info = texture_levels[level].info;
  int w = int(info.y), h = int(info.z);
  vec2 x = uv * vec2(w, h) - 0.5;
  vec2 cell = floor(x);
  vec2 f = x - cell;
  int i0 = int(mod(cell.x, float(w))), j0 = int(mod(cell.y, float(h)));
  int i1 = (i0 + 1) % w, j1 = (j0 + 1) % h;
  vec4 t00 = texels[info.x + uint(j0 * w + i0)], t10 = texels[info.x + uint(j0 * w + i1)];
  vec4 t01 = texels[info.x + uint(j1 * w + i0)], t11 = texels[info.x + uint(j1 * w + i1)];
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

vec4 sample_trilinear(uint first, uint count, vec2 uv, float lod) {
  float l0 = floor(lod);
  uint level = first + uint(l0);
  if (l0 + 1.0 >= float(count)) return sample_level(level, uv);
  return mix(sample_level(level, uv), sample_level(level + 1u, uv), lod - l0);
}

float colormap_position(GpuColormap map, float value) {
  return (value - map.domain.x) / (map.domain.y - map.domain.x);
}

vec3 colormap_at(GpuColormap map, float value) {
  float t = colormap_position(map, value);
  uint first = map.info.x, last = map.info.x + map.info.y - 1u;
  if (!(t > colormap_points[first].w)) return colormap_points[first].rgb;  // NaN takes the first colour
  if (t >= colormap_points[last].w) return colormap_points[last].rgb;
  uint i = first;
  while (colormap_points[i + 1u].w <= t) ++i;
  vec4 a = colormap_points[i], b = colormap_points[i + 1u];
  return map.info.z == 1u ? a.rgb : mix(a.rgb, b.rgb, (t - a.w) / (b.w - a.w));
}

// E[colormap(t)] for t ~ N(mu, sigma^2) in texture values: the segments and end tails of the map
// (lib/colormap_filter.glsl), in the map's own parameter.
vec3 colormap_filtered(GpuColormap map, float mu, float sigma) {
  float scale = 1.0 / (map.domain.y - map.domain.x);
  float m = colormap_position(map, mu), s = sigma * abs(scale);
  uint first = map.info.x, last = map.info.x + map.info.y - 1u;
  vec3 sum = colormap_tail_below_gaussian(colormap_points[first].w, colormap_points[first].rgb, m, s) +
             colormap_tail_above_gaussian(colormap_points[last].w, colormap_points[last].rgb, m, s);
  for (uint i = first; i < last; ++i) {
    vec4 a = colormap_points[i], b = colormap_points[i + 1u];
    sum += colormap_segment_gaussian(a.w, b.w, a.rgb, map.info.z == 1u ? a.rgb : b.rgb, m, s);
  }
  return sum;
}

// The moments (E[t], E[t^2]) of the texture over an isotropic footprint at `lod`. The finest level
// counts as variance-free: a footprint within one texel sees the bilinear texture, whose value there
// is what `naive` samples, so `filtered` equals `naive` under magnification.
vec2 footprint_moments(uint first, uint count, vec2 uv, float lod) {
  float l0 = floor(lod);
  uint level = uint(l0);
  vec4 a = sample_level(first + level, uv);
  vec4 b = level + 1u < count ? sample_level(first + level + 1u, uv) : a;
  if (level == 0u) a.y = a.x * a.x;
  return mix(a.xy, b.xy, lod - l0);
}

// The albedo of a colour-mapped texture at the hit, by the method of kTextureMethod, averaged over
// the taps of the anisotropic footprint with uv axes duv_dx, duv_dy (unused by naive). Moments of
// the taps combine exactly (a mixture's E[t] and E[t^2] are the means of the taps').
vec3 textured_albedo(GpuMaterial m, vec2 uv, vec2 duv_dx, vec2 duv_dy) {
  GpuColormap map = colormaps[m.texture.w];
  if (kTextureMethod == 0u) return colormap_at(map, sample_level(m.texture.x, uv).x);
  uvec4 level0 = texture_levels[m.texture.x].info;
  AnisotropicFootprint f =
      anisotropic_footprint(duv_dx, duv_dy, vec2(level0.yz), float(m.texture.y), kMaxAnisotropicTaps);
  vec3 colour = vec3(0.0);
  vec2 moments = vec2(0.0);
  for (float k = 0.0; k < f.taps; k += 1.0) {
    vec2 tap = uv + f.major * ((k + 0.5) / f.taps - 0.5);
    if (kTextureMethod == 2u)
      colour += sample_trilinear(m.texture.z, m.texture.y, tap, f.lod).rgb;
    else if (kTextureMethod == 1u)
      colour += colormap_at(map, sample_trilinear(m.texture.x, m.texture.y, tap, f.lod).x);
    else
      moments += footprint_moments(m.texture.x, m.texture.y, tap, f.lod);
  }
  if (kTextureMethod != 3u) return colour / f.taps;
  moments /= f.taps;
  return colormap_filtered(map, moments.x, sqrt(max(moments.y - moments.x * moments.x, 0.0)));
}

// ---------------------------------------------------------------- shading

vec3 camera_ray(vec2 film) {
  return camera_ray_direction(globals.camera_forward.xyz, globals.camera_right.xyz, globals.camera_up.xyz, film,
                              vec2(globals.image.xy));
}

// Radiance along the camera ray through `film` (pixels); `pixel_step` is the film distance to the
// neighbouring rays whose hits span the texture footprint.
vec3 radiance(vec2 film, float pixel_step) {
  vec3 o = globals.camera_origin.xyz;
  vec3 d = camera_ray(film);
  Hit hit = trace(o, d, 0.0, kInfinity);
  if (hit.material == kNoHit) return globals.background.rgb;
  vec3 p = o + hit.t * d;
  vec3 n = normalize(hit.normal);
  if (dot(n, d) > 0.0) n = -n;
  vec3 l = globals.light_direction.xyz;
  // Offset the shadow ray's origin by a distance relative to the scene's scale at p.
  vec3 shadow_origin = p + n * (1e-4 * max(1.0, length(p)));
  float visibility = dot(n, l) > 0.0 && trace(shadow_origin, l, 0.0, kInfinity).material != kNoHit ? 0.0 : 1.0;
  GpuMaterial m = materials[hit.material];
  if (kHasMicroflake && m.kind.x == FACET_MATERIAL_MICROFLAKE)
    return microflake_radiance(int(m.kind.y), m.params.x, m.albedo.rgb, n, -d, l, globals.light_irradiance.rgb,
                               visibility, globals.ambient.rgb);
  vec3 albedo = m.albedo.rgb;
  if (kHasTexture && m.kind.x == FACET_MATERIAL_COLORMAP_TEXTURE) {
    SurfaceUv s = surface_uv(hit, p);
    vec2 duv_dx = vec2(0.0), duv_dy = vec2(0.0);
    if (kTextureMethod != 0u) {
      duv_dx = uv_differential(o, camera_ray(film + vec2(pixel_step, 0.0)), p, n, s.dpdu, s.dpdv);
      duv_dy = uv_differential(o, camera_ray(film + vec2(0.0, pixel_step)), p, n, s.dpdu, s.dpdv);
    }
    albedo = textured_albedo(m, s.uv, duv_dx, duv_dy);
  }
  return lambert_radiance(albedo, n, l, globals.light_irradiance.rgb, visibility, globals.ambient.rgb);
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy + tile.rect.xy;
  if (gl_GlobalInvocationID.x >= tile.rect.z || gl_GlobalInvocationID.y >= tile.rect.w) return;
  vec3 sum = vec3(0.0);
  float step = 1.0 / float(kSamplesPerAxis);
  for (uint sy = 0u; sy < kSamplesPerAxis; ++sy)
    for (uint sx = 0u; sx < kSamplesPerAxis; ++sx)
      sum += radiance(vec2(pixel) + (vec2(sx, sy) + 0.5) * step, step);
  pixels[gl_GlobalInvocationID.y * tile.rect.z + gl_GlobalInvocationID.x] =
      vec4(sum / float(kSamplesPerAxis * kSamplesPerAxis), 1.0);
}
