// Colour-mapped microsurfaces in the direct pass (docs/microsurface_filtering.md): a height field on a
// finite plane, shaded by the method of kTextureMethod (declared by the including shader):
//   0 naive     the traced height field (render/heightfield_trace.glsl), shaded per hit as the
//               reference shades a sample (microsurface_traced_radiance); ss:K averages K x K of them
//   1 mip       the footprint's mean z and mean slope through the same point shading (the common wrong answer)
//   2 colormip  the footprint's mean albedo (MIP chain of the colour-mapped field), mean slope
//   3, 4 filtered  the footprint's Gaussian heights and slopes (lib/microsurface_filter.glsl): visible
//               slopes D_s and visible heights for the view, Smith shadowing for the light, the colour
//               maps integrated against them, the LEAN-convolved Beckmann lobe
// Material fields: renderer/gpu/microsurface_upload.hpp.
#ifndef FACET_RENDER_MICROSURFACE_SHADING_GLSL
#define FACET_RENDER_MICROSURFACE_SHADING_GLSL
#include "lib/beckmann_facet.glsl"
#include "lib/lambert.glsl"
#include "lib/microsurface_filter.glsl"
#include "lib/texture_footprint.glsl"
#include "render/heightfield_trace.glsl"
#include "render/scene_bindings.glsl"
#include "render/texture_sampling.glsl"

// Whether microsurface m has a height or a slope colour map, and the scene's pipeline its code
// (kMicrosurfaceHeightMaps, kMicrosurfaceSlopeMaps, declared by the including shader).
bool microsurface_has_height_map(GpuMaterial m) { return kMicrosurfaceHeightMaps && m.texture.z != FACET_NO_COLORMAP; }
bool microsurface_has_slope_map(GpuMaterial m) { return kMicrosurfaceSlopeMaps && m.texture.w != FACET_NO_COLORMAP; }

// height_colormap(z) slope_colormap(|s|), each factor only when the material has it.
vec3 microsurface_height_colour(GpuMaterial m, float z) {
  return microsurface_has_height_map(m) ? colormap_at(colormap_record(m.texture.z), z + m.params.z) : vec3(1.0);
}
vec3 microsurface_slope_colour(GpuMaterial m, vec2 s) {
  return microsurface_has_slope_map(m) ? colormap_at(colormap_record(m.texture.w), length(s)) : vec3(1.0);
}

struct MicrosurfaceMoments {
  vec4 m0;  // E[z], E[z^2], E[s_x], E[s_y]
  vec4 m1;  // E[s_x^2], E[s_y^2], E[s_x s_y], -
};

MicrosurfaceMoments microsurface_point_moments(vec3 p) {
  return MicrosurfaceMoments(vec4(p.x, p.x * p.x, p.yz), vec4(p.y * p.y, p.z * p.z, p.y * p.z, 0.0));
}

// A point (z, s_x, s_y) as statistics: no variance (up to the floors of microsurface_filter.glsl).
MicrosurfaceStatistics microsurface_point_statistics(vec3 p) {
  MicrosurfaceMoments point = microsurface_point_moments(p);
  return microsurface_statistics(point.m0, point.m1);
}

// The moments of one footprint tap at texel coordinates q: trilinear in the moment chains at lod,
// blended toward the point value at q with `point_weight` (footprints narrower than two texels: a
// footprint within one texel sees the bilinear surface at its point, so filtered equals naive there).
MicrosurfaceMoments microsurface_tap_moments(GpuMaterial m, vec2 q, vec2 size, float lod, float point_weight) {
  uint first = m.texture.x + 1u, count = m.texture.y;
  vec2 uv = q / size;
  // mip and colormip use the means only: the second-moment chain is read by filtered alone, which only
  // the program that traces height fields runs on microsurfaces.
  MicrosurfaceMoments chain = MicrosurfaceMoments(sample_trilinear(first, count, uv, lod, false), vec4(0.0));
#ifdef FACET_HEIGHT_FIELDS
  if (kTextureMethod >= 3u) chain.m1 = sample_trilinear(first + count, count, uv, lod, false);
#endif
  if (point_weight <= 0.0) return chain;
  MicrosurfaceMoments point = microsurface_point_moments(heightfield_point(heightfield_quads(m), q, m.albedo.w));
  return MicrosurfaceMoments(mix(chain.m0, point.m0, point_weight), mix(chain.m1, point.m1, point_weight));
}

// Lambert with the facet normal of slope s plus the Beckmann lobe on slopes `stats`; v, l in the plane frame.
vec3 microsurface_facet_radiance(GpuMaterial m, vec3 albedo, MicrosurfaceStatistics stats, vec3 v, vec3 l,
                                 float visibility) {
  float cos_l = max(dot(microsurface_normal(stats.s_mean), l), 0.0);
  vec3 diffuse = albedo * FACET_INV_PI * (globals.light_irradiance.rgb * (cos_l * visibility) + globals.ambient.rgb);
  if (!kMicrosurfaceLobes || m.kind.y == 0u) return diffuse;
  return diffuse + globals.light_irradiance.rgb * m.albedo.rgb * (microsurface_specular(stats, m.params.xy, l, v, vec4(0.0)) * visibility);
}

// A traced hit at field texel q, shaded as the reference shades a sample (cpu/reference_renderer.cpp):
// the colour maps at (H1)-(H2), Lambert and the facet's own Beckmann lobe with the micro-normal n
// (unit, facing the viewer); v, l in world space. filtered averages the lobe over the pixel, whose
// neighbouring views are v_x and v_y and whose texels one pixel step away are q +- dq_dx, q +- dq_dy, where the
// field's normals have turned (eqs. P2, P3 of docs/microsurface_filtering.md); naive takes it at v and n.
vec3 microsurface_traced_radiance(GpuMaterial m, GpuPlane plane, vec2 q, vec3 n, vec3 v, vec3 l, float visibility,
                                  vec3 v_x, vec3 v_y, vec2 dq_dx, vec2 dq_dy) {
  uint quads = heightfield_quads(m);
  vec3 point = heightfield_point(quads, q, m.albedo.w);
  vec3 albedo = microsurface_height_colour(m, point.x) * microsurface_slope_colour(m, point.yz);
  vec3 c = lambert_radiance(albedo, n, l, globals.light_irradiance.rgb, visibility, globals.ambient.rgb);
  if (!kMicrosurfaceLobes || m.kind.y == 0u || visibility == 0.0) return c;
  float f_cos;
  if (kTextureMethod >= 3u) {
    // n faces the viewer, the field's normals lie on the plane's upper side: the neighbours' follow n's side
    float side = dot(n, plane.normal.xyz) < 0.0 ? -1.0 : 1.0;
    vec3 turned[4];  // the field's normals one pixel step away toward +x, -x, +y, -y
    for (int k = 0; k < 4; ++k) {
      vec2 dq = (k < 2 ? dq_dx : dq_dy) * (k % 2 == 0 ? 1.0 : -1.0);
      turned[k] = side * normalize(heightfield_normal(plane, heightfield_point(quads, q + dq, m.albedo.w)));
    }
    f_cos = beckmann_facet_specular_over_pixel(n, plane.tangent.xyz, v, l, m.params.xy, v_x, v_y, turned[0], turned[1],
                                               turned[2], turned[3]);
  } else {
    f_cos = beckmann_facet_specular(n, plane.tangent.xyz, v, l, m.params.xy);
  }
  return c + globals.light_irradiance.rgb * m.albedo.rgb * (f_cos * visibility);
}

// The Beckmann lobe on the footprint's slopes in the frame of its mean facet (normal n of the mean
// slope, tangent the plane's projected onto it): the LEAN convolution about slope 0 there. A footprint
// on a bump's flank is a tilted patch; in the plane's slope space its lobe would be divided by the
// plane's cos(theta_v), which at grazing views is far below the patch's own (radiance 10x too high on
// scenes/microsurface_horizon.json). v, l in the plane frame, as are the pixel's neighbouring views v_x, v_y,
// over which D is averaged (eq. P2 of docs/microsurface_filtering.md).
float microsurface_mean_facet_specular(MicrosurfaceStatistics stats, vec2 alpha, vec3 l, vec3 v, vec3 v_x, vec3 v_y) {
  BeckmannFacetFrame f = beckmann_facet_frame(microsurface_normal(stats.s_mean), vec3(1.0, 0.0, 0.0));
  MicrosurfaceStatistics centred = stats;
  centred.s_mean = vec2(0.0);
  vec3 l_facet = beckmann_facet_local(f, l), v_facet = beckmann_facet_local(f, v);
  vec4 steps = microsurface_pixel_half_slope_steps(l_facet, v_facet, beckmann_facet_local(f, v_x), beckmann_facet_local(f, v_y));
  return microsurface_specular(centred, alpha, l_facet, v_facet, steps);
}

// Node k of the visible heights with CDF C^(1 + lambda) in standard units (microsurface_height_node with mean 0
// and deviation 1), interpolated in microsurface m's node table (renderer/gpu/microsurface_upload.hpp): one
// texel where the quantile would cost a logarithm, expm1, a square root and a Newton step a node.
float microsurface_height_node_z(GpuMaterial m, int k, float lambda) {
  uvec4 table = texture_level_at(heightfield_quads(m) + 1u).info;
  vec2 at = microsurface_node_table_position(lambda);
  vec4 z = texel_at(table.x + uint(at.x) * uint(MS_HEIGHT_NODES) + uint(k));
  return mix(z.x, z.y, at.y);
}

// The filtered radiance of a footprint with Gaussian statistics `stats` (docs/microsurface_filtering.md
// eq. M7): E/pi V H_lit S_cos + E_amb/pi H S + V E R f_spec; v_x, v_y: the views one pixel step away. `side`
// is -1 where the field is seen from below: `stats` are then its mirror image's (microsurface_seen_statistics),
// whose heights are the field's negated, and the height map reads the field's own, side h.
vec3 microsurface_filtered_radiance(GpuMaterial m, MicrosurfaceStatistics stats, float side, vec3 v, vec3 l,
                                    float visibility, vec3 v_x, vec3 v_y) {
  MicrosurfaceVisibility vis = microsurface_visibility(stats, v, l);
  vec3 slope_sum = vec3(0.0), slope_cos_sum = vec3(0.0);
  // Without a slope colour map only the smooth cosine is integrated: the 3 x 3 rule suffices there.
  // Each of the two node sums is one loop over its two indices (next_row_major), in the nested loops' order.
  int slope_nodes = microsurface_has_slope_map(m) ? MS_SLOPE_NODES : MS_SLOPE_NODES_COSINE;
  ivec2 ij = ivec2(0);
  for (int node_index = 0; node_index < slope_nodes * slope_nodes; ++node_index) {
    MicrosurfaceSlopeNode node = microsurface_slope_node(vis.ds, slope_nodes, ij.x, ij.y);
    vec3 a = node.weight * microsurface_slope_colour(m, node.s);
    slope_sum += a;
    slope_cos_sum += a * max(dot(microsurface_normal(node.s), l), 0.0);
    ij = next_row_major(ij, slope_nodes);
  }
  vec3 heights = vec3(1.0), heights_lit = vec3(vis.lit);
  if (microsurface_has_height_map(m)) {
    heights = vec3(0.0);
    heights_lit = vec3(0.0);
    float a = microsurface_lit_exponent(vis);
    bool lit_on_visible_nodes = a <= MS_LIT_SHARED_MAX;
    // Node k of the visible heights, then, where the lit weights are not shared, of the visible and lit
    // ones: one call of the node and its colour (each call site is compiled on its own).
    int lit_count = lit_on_visible_nodes ? 1 : 2;
    ivec2 node_lit = ivec2(0);  // the node k, and whether its heights are the visible and lit ones
    for (int node_index = 0; node_index < MS_HEIGHT_NODES * lit_count; ++node_index) {
      int k = node_lit.x, lit_nodes = node_lit.y;
      float lambda = lit_nodes == 0 ? vis.lambda_v : vis.lambda_v + vis.lambda_l;
      vec3 c = microsurface_height_colour(m, side * (stats.h_mean + stats.h_sigma * microsurface_height_node_z(m, k, lambda)));
      if (lit_nodes == 1)
        heights_lit += c / float(MS_HEIGHT_NODES);
      else {
        heights += c;
        if (lit_on_visible_nodes) heights_lit += microsurface_lit_weight(k, a) * c;
      }
      node_lit = next_row_major(node_lit, lit_count);
    }
    heights /= float(MS_HEIGHT_NODES);
    heights_lit *= vis.lit;
  }
  vec3 radiance = FACET_INV_PI * (globals.light_irradiance.rgb * visibility * heights_lit * slope_cos_sum +
                                  globals.ambient.rgb * heights * slope_sum);
  if (!kMicrosurfaceLobes || m.kind.y == 0u) return radiance;
  return radiance + globals.light_irradiance.rgb * m.albedo.rgb * (microsurface_mean_facet_specular(stats, m.params.xy, l, v, v_x, v_y) * visibility);
}

// The pixel's footprint on microsurface `m` on `plane`, hit at p by the ray o + t d; d_dx, d_dy: the
// rays through the neighbouring pixel positions, which meet the plane through p with normal
// n_surface (the rectangle's, or the traced surface's: T4 of docs/microsurface_filtering.md); their
// offsets are projected onto the rectangle (the field is a graph over it). q: the hit in texels from
// the rectangle's (-w/2, -h/2) corner, where the field's vertex (0, 0) sits; size: the field in
// texels; duv_*: the footprint's axes in field uv (period = the field), as for colour-mapped textures;
// d_dx, d_dy: the neighbouring rays themselves (the pixel's spread of views).
struct MicrosurfaceFootprint {
  vec2 q, size, duv_dx, duv_dy;
  vec3 d_dx, d_dy;
};

MicrosurfaceFootprint microsurface_footprint(GpuMaterial m, GpuPlane plane, vec3 o, vec3 d, vec3 p, vec3 d_dx,
                                             vec3 d_dy, vec3 n_surface) {
  vec3 t = plane.tangent.xyz, n = plane.normal.xyz, b = cross(n, t);
  float delta = m.albedo.w;
  vec2 size = vec2(texture_level_at(m.texture.x).info.yz);
  vec3 r = p - plane.point.xyz;
  vec3 dpdu = t * (size.x * delta), dpdv = b * (size.y * delta);
  return MicrosurfaceFootprint((vec2(dot(r, t), dot(r, b)) + plane.uv_half_size.zw) / delta, size,
                               uv_differential(o, d_dx, p, n_surface, dpdu, dpdv),
                               uv_differential(o, d_dy, p, n_surface, dpdu, dpdv), d_dx, d_dy);
}

// The pixel's footprint on the surface `filtered` traces, from its footprint flat_fp on the flat
// rectangle (T4 of docs/microsurface_filtering.md): the neighbouring rays meet the plane through the
// hit p whose normal is the field's mean slope over flat_fp (the first moment chain at its level).
// On a flank facing the viewer that footprint is shorter than flat_fp; on a flank the rays graze it
// grows without bound, where the real surface curves away within the bump, so each axis is kept no
// longer than flat_fp's.
MicrosurfaceFootprint microsurface_footprint_on_surface(GpuMaterial m, GpuPlane plane, vec3 o, vec3 d, vec3 p,
                                                        vec3 d_dx, vec3 d_dy, MicrosurfaceFootprint flat_fp) {
  float lod = anisotropic_footprint(flat_fp.duv_dx, flat_fp.duv_dy, flat_fp.size, float(m.texture.y), kMaxAnisotropicTaps).lod;
  vec2 s = sample_trilinear(m.texture.x + 1u, m.texture.y, flat_fp.q / flat_fp.size, lod, false).zw;
  vec3 t = plane.tangent.xyz, n = plane.normal.xyz;
  MicrosurfaceFootprint fp = microsurface_footprint(m, plane, o, d, p, d_dx, d_dy, normalize(n - s.x * t - s.y * cross(n, t)));
  if (length(fp.duv_dx) > length(flat_fp.duv_dx)) fp.duv_dx = flat_fp.duv_dx;
  if (length(fp.duv_dy) > length(flat_fp.duv_dy)) fp.duv_dy = flat_fp.duv_dy;
  return fp;
}

// The footprint's width in texels: the longer of its two axes.
float microsurface_footprint_texels(MicrosurfaceFootprint fp) {
  return max(length(fp.duv_dx * fp.size), length(fp.duv_dy * fp.size));
}

// How much of `filtered`'s answer comes from the traced field: 1 where the footprint's longer axis is
// within one texel (one ray resolves the bilinear surface), 0 from two texels on (the statistics),
// linear in between (docs/microsurface_filtering.md, "Across scales").
float microsurface_trace_weight(MicrosurfaceFootprint fp) {
  return clamp(2.0 - microsurface_footprint_texels(fp), 0.0, 1.0);
}

// The statistics of the field as seen from `side` (1: above the plane; -1: below, where it is shaded as its
// mirror image z -> -z seen from above, whose heights and slopes are the field's negated; the slopes'
// covariance is unchanged: eq. M10 of docs/microsurface_filtering.md).
MicrosurfaceStatistics microsurface_seen_statistics(MicrosurfaceStatistics stats, float side) {
  stats.h_mean *= side;
  stats.s_mean *= side;
  return stats;
}

// The unit direction toward the viewer of a ray d (any length) in `frame`.
vec3 microsurface_view(BeckmannFacetFrame frame, vec3 d) {
  return vec3(dot(-d, frame.t), dot(-d, frame.b), dot(-d, frame.n)) / length(d);
}

// The radiance of microsurface `m` on `plane` by the statistics of footprint fp (methods mip, colormip,
// filtered) of the ray direction d; visibility of the light from the hit.
vec3 microsurface_radiance(GpuMaterial m, GpuPlane plane, MicrosurfaceFootprint fp, vec3 d, vec3 l_world,
                           float visibility, bool traced) {
  vec3 t = plane.tangent.xyz, n = plane.normal.xyz, b = cross(n, t);
  float delta = m.albedo.w;
  vec2 q = fp.q, size = fp.size, duv_dx = fp.duv_dx, duv_dy = fp.duv_dy;
  BeckmannFacetFrame frame = BeckmannFacetFrame(t, b, n);  // the plane's
  vec3 v = microsurface_view(frame, d), v_x = microsurface_view(frame, fp.d_dx), v_y = microsurface_view(frame, fp.d_dy);
  vec3 l = vec3(dot(l_world, t), dot(l_world, b), dot(l_world, n));
  // Seen from below, the field is shaded as its mirror image seen from above (M10): views and light mirrored
  // here, heights and slopes by microsurface_seen_statistics.
  float side = v.z < 0.0 ? -1.0 : 1.0;
  if (side < 0.0) {
    v.z = -v.z;
    l.z = -l.z;
    v_x.z = -v_x.z;
    v_y.z = -v_y.z;
  }
  v.z = max(v.z, 1e-6);
  // Parallax: the pixel's rays meet the real surface displaced from the flat-plane hit by z cot(theta_v)
  // along the view's azimuth, a spread of standard deviation sigma_h cot(theta_v) (sigma_h of the whole
  // field: the coarsest moment level); the box of that spread, sqrt(12) sigma_h cot(theta_v) long, is
  // added to the footprint axis closer to the view's azimuth. Zero straight down, large at grazing views.
  vec4 field = texel_at(texture_level_at(m.texture.x + m.texture.y).info.x);
  vec2 parallax = traced ? vec2(0.0) : sqrt(12.0) * sqrt(max(field.y - field.x * field.x, 0.0)) * (v.xy / v.z) / (size * delta);
  float along_x = abs(dot(duv_dx, parallax)) * length(duv_dy), along_y = abs(dot(duv_dy, parallax)) * length(duv_dx);
  if (along_x >= along_y)
    duv_dx += dot(duv_dx, parallax) >= 0.0 ? parallax : -parallax;
  else
    duv_dy += dot(duv_dy, parallax) >= 0.0 ? parallax : -parallax;
  AnisotropicFootprint f = anisotropic_footprint(duv_dx, duv_dy, size, float(m.texture.y), kMaxAnisotropicTaps);
  float point_weight = clamp(2.0 - f.width, 0.0, 1.0);
  MicrosurfaceMoments sum = MicrosurfaceMoments(vec4(0.0), vec4(0.0));
  vec3 albedo = vec3(0.0);
  for (float k = 0.0; k < f.taps; k += 1.0) {
    vec2 tap = q + f.major * size * ((k + 0.5) / f.taps - 0.5);
    MicrosurfaceMoments tm = microsurface_tap_moments(m, tap, size, f.lod, point_weight);
    sum.m0 += tm.m0;
    sum.m1 += tm.m1;
#ifndef FACET_HEIGHT_FIELDS  // colormip shades the flat rectangle only
    if (kTextureMethod == 2u) {
      vec3 chain = sample_trilinear(m.texture.x + 1u + 2u * m.texture.y, m.texture.y, tap / size, f.lod, false).rgb;
      if (point_weight > 0.0) {
        vec3 point = heightfield_point(heightfield_quads(m), tap, delta);
        chain = mix(chain, microsurface_height_colour(m, point.x) * microsurface_slope_colour(m, point.yz), point_weight);
      }
      albedo += chain;
    }
#endif
  }
  MicrosurfaceStatistics stats = microsurface_statistics(sum.m0 / f.taps, sum.m1 / f.taps);
  MicrosurfaceStatistics seen = microsurface_seen_statistics(stats, side);  // what the view and light meet (M10)
  // The program that traces height fields shades footprints for filtered alone; the other, for mip and
  // colormip alone (renderer/gpu/direct_pass.cpp): each compiles only its own methods' code.
#ifdef FACET_HEIGHT_FIELDS
  return microsurface_filtered_radiance(m, seen, side, v, l, visibility, v_x, v_y);
#else
  // mip and colormip: the mean slope as a point, no variance; it lights the mirror image's facet (M10), the
  // colours are the field's own.
  MicrosurfaceStatistics mean_point = microsurface_point_statistics(vec3(seen.h_mean, seen.s_mean));
  if (kTextureMethod == 1u)
    albedo = microsurface_height_colour(m, stats.h_mean) * microsurface_slope_colour(m, stats.s_mean);
  else
    albedo /= f.taps;
  return microsurface_facet_radiance(m, albedo, mean_point, v, l, visibility);
#endif
}

#endif
