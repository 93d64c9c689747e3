// Colour-mapped textures in the direct pass: bilinear and trilinear lookups of the MIP chains, the
// colour map at a point and against a Gaussian, and the albedo of a texture by the method selected
// with the specialization constant kTextureMethod (declared by the including shader).
#ifndef FACET_RENDER_TEXTURE_SAMPLING_GLSL
#define FACET_RENDER_TEXTURE_SAMPLING_GLSL
#include "lib/colormap_filter.glsl"
#include "lib/texture_footprint.glsl"
#include "render/scene_bindings.glsl"

const float kMaxAnisotropicTaps = 8.0;

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

#endif
