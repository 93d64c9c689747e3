// Primary rays through the scene's planes, spheres and BVH of triangles; direct lighting from the
// directional light (with a shadow ray) plus the ambient fill, for every macro-surface material.
// Specialization constants (ids named FACET_RENDER_SPEC_* in layout/render_layout.glsl, with the
// binding slots and the workgroup size) select what a scene and a method use, within what the variant compiles in:
//   kHasMicroflake     microflake half-spaces (lib/microflake_shading.glsl)
//   kHasTexture        colour-mapped textures
//   kTextureMethod     0 naive (finest level, colour map per sample), 1 mip (MIP-mapped texture, then
//                      colour map), 2 colormip (MIP-mapped colour-mapped texture), 3 filtered (the
//                      footprint's Gaussian N(mu, sigma^2) integrated against the colour map exactly),
//                      4 filtered:table (the same Gaussian looked up in the map's prefiltered table)
//   kHasDiffraction    diffraction gratings (render/diffraction_shading.glsl)
//   kDiffractionMethod how a grating's spectrum becomes a colour: 0 spectral (wavelength samples),
//                      1 preintegrated, 2 orders (render/diffraction_shading.glsl)
//   kHasMicrosurface   colour-mapped microsurfaces on finite planes, by kTextureMethod (naive,
//                      filtered and filtered:table, at any ss:K, trace their height fields with
//                      render_direct_fields.comp: render/heightfield_trace.glsl)
//   kHasSpheres, kHasTriangles  the scene has spheres / meshes (render/trace.glsl): lavapipe runs
//                      the body of a loop over no primitives once, masked, so absent kinds are compiled out
//   kPreintegratedSlices, kPreintegratedSliceWords  how many word bindings the `preintegrated` tables
//                      span and the words each slice starts cells in (render/diffraction_bindings.glsl)
//   kWritesAovs        the auxiliary outputs (depth, normal, uv, error estimate) are accumulated in
//                      the pixel buffer after the colours (renderer/gpu/direct_pass.cpp, docs/aov.md)
//   kEstimatesError    some dispatch computes the texture's error estimate (the error channel, or
//                      filtered:adaptive's ranking; GpuTile::list.y leaves it out per dispatch); without,
//                      its code is compiled out, for lavapipe runs a skipped branch masked all the same
//   kMicrosurfaceHeightMaps, kMicrosurfaceSlopeMaps, kMicrosurfaceLobes  some microsurface of the scene has
//                      a height colour map, a slope colour map, a specular lobe: the others' code is left
//                      out (render/microsurface_shading.glsl), for the same reason
//   kCountsWork        each sample's work replaces its colour: (FMA-equivalents, texel fetches, 0, 1),
//                      counted by increments renderer/gpu/work_counter.hpp adds to the SPIR-V
//                      (docs/render_speed.md, "Work per pixel"); off, the counters are dead code
// Tracing, the scene's buffers and each material family's shading live in render/*.glsl.
// Two programs include this file: render_direct.comp, and render_direct_fields.comp, which defines
// FACET_HEIGHT_FIELDS and so traces microsurfaces' height fields. Lavapipe compiles every call of
// the traversal it inlines even where a specialization constant makes it dead: the tracer's three
// calls would triple the pipeline set-up of every scene (1.4 s -> 3.4 s for colormap_objects).
// Each program is built in variants (shaders/CMakeLists.txt) that compile in only some of the code:
// FACET_VARIANT_HAS (render/variant_code.glsl) guards each family's, primitive kind's and method's calls.
#ifndef FACET_RENDER_DIRECT_PASS_GLSL
#define FACET_RENDER_DIRECT_PASS_GLSL

#include "layout/render_layout.glsl"
#include "render/variant_code.glsl"

layout(local_size_x = FACET_RENDER_WORKGROUP, local_size_y = FACET_RENDER_WORKGROUP) in;
layout(constant_id = FACET_RENDER_SPEC_HAS_MICROFLAKE) const bool kHasMicroflake = false;
layout(constant_id = FACET_RENDER_SPEC_HAS_TEXTURE) const bool kHasTexture = false;
layout(constant_id = FACET_RENDER_SPEC_TEXTURE_METHOD) const uint kTextureMethod = 0u;
layout(constant_id = FACET_RENDER_SPEC_HAS_DIFFRACTION) const bool kHasDiffraction = false;
layout(constant_id = FACET_RENDER_SPEC_DIFFRACTION_METHOD) const uint kDiffractionMethod = 0u;
layout(constant_id = FACET_RENDER_SPEC_HAS_MICROSURFACE) const bool kHasMicrosurface = false;  // render/microsurface_shading.glsl
layout(constant_id = FACET_RENDER_SPEC_HAS_SPHERES) const bool kHasSpheres = true;
layout(constant_id = FACET_RENDER_SPEC_HAS_TRIANGLES) const bool kHasTriangles = true;
layout(constant_id = FACET_RENDER_SPEC_PREINTEGRATED_SLICES) const uint kPreintegratedSlices = 1u;
layout(constant_id = FACET_RENDER_SPEC_PREINTEGRATED_SLICE_WORDS) const uint kPreintegratedSliceWords = 0xffffffffu;
layout(constant_id = FACET_RENDER_SPEC_AOVS) const bool kWritesAovs = false;
layout(constant_id = FACET_RENDER_SPEC_COUNTS_WORK) const bool kCountsWork = false;
layout(constant_id = FACET_RENDER_SPEC_ESTIMATES_ERROR) const bool kEstimatesError = false;  // render/texture_sampling.glsl
layout(constant_id = FACET_RENDER_SPEC_MICROSURFACE_HEIGHT_MAPS) const bool kMicrosurfaceHeightMaps = true;
layout(constant_id = FACET_RENDER_SPEC_MICROSURFACE_SLOPE_MAPS) const bool kMicrosurfaceSlopeMaps = true;
layout(constant_id = FACET_RENDER_SPEC_MICROSURFACE_LOBES) const bool kMicrosurfaceLobes = true;
layout(constant_id = FACET_RENDER_SPEC_HAS_LINEAR_COLORMAPS) const bool kHasLinearColormaps = true;
layout(constant_id = FACET_RENDER_SPEC_HAS_STEP_COLORMAPS) const bool kHasStepColormaps = true;
layout(constant_id = FACET_RENDER_SPEC_WHOLE_MIP_TEXELS) const bool kWholeMipTexels = false;  // render/texture_sampling.glsl
layout(constant_id = FACET_RENDER_SPEC_STEP_COLORMAP_POINTS) const uint kStepColormapPoints = 0u;      // the same
layout(constant_id = FACET_RENDER_SPEC_LINEAR_COLORMAP_POINTS) const uint kLinearColormapPoints = 0u;  // the same
layout(constant_id = FACET_RENDER_SPEC_COLORMAP_SEARCH_STEPS) const uint kColormapSearchSteps = 32u;   // the same
layout(constant_id = FACET_RENDER_SPEC_COLORMAP_DIVIDES) const bool kColormapDivides = true;           // the same
layout(constant_id = FACET_RENDER_SPEC_PLANE_TRIPS) const uint kPlaneTrips = FACET_RENDER_LOOPED_TRIPS;    // render/trace.glsl
layout(constant_id = FACET_RENDER_SPEC_SPHERE_TRIPS) const uint kSphereTrips = FACET_RENDER_LOOPED_TRIPS;  // the same
// The dispatch that shades the queue of filtered's microsurface statistics (render/microsurface_statistics_queue.glsl)
// instead of tracing the tile.
layout(constant_id = FACET_RENDER_SPEC_STATISTICS_PASS) const bool kStatisticsPass = false;
// naive, ss:K and filtered see a microsurface's geometry as the reference does: its height field,
// traced (render/heightfield_trace.glsl); mip and colormip shade the flat rectangle.
#ifdef FACET_HEIGHT_FIELDS
const bool kTracesHeightFields = kHasMicrosurface && kTextureMethod != 1u && kTextureMethod != 2u;
#else
const bool kTracesHeightFields = false;
#endif

#include "lib/camera.glsl"
#include "lib/lambert.glsl"
#include "lib/microflake_shading.glsl"
#include "lib/microflake_pixel_lobe.glsl"
#include "render/diffraction_shading.glsl"
#include "render/scene_bindings.glsl"
#include "render/texture_sampling.glsl"
#include "render/microsurface_shading.glsl"
#include "render/trace.glsl"
#ifdef FACET_HEIGHT_FIELDS
#include "render/microsurface_field.glsl"
#endif

// This invocation's auxiliary outputs (kWritesAovs), set by radiance() and shade(): camera-space z and
// the shading normal (0 on a miss); uv, the texture's error estimate (docs/error_estimate.md) and 1 where
// a texture term models the hit; whether the hit's shadow ray reached the light (1 where none was cast,
// 0 on a miss), where a shadow's edge lies between neighbours (eq. 3).
vec4 aov_depth_normal = vec4(0.0);
vec4 aov_uv_error = vec4(0.0);
vec4 aov_lit = vec4(0.0);
// This invocation's work so far (kCountsWork): renderer/gpu/work_counter.hpp finds them by name.
uint facet_work_fma = 0u;
uint facet_work_reads = 0u;
// The texture's error estimate (docs/error_estimate.md). kappa of eq. 1: the filtered colour's error per unit
// of the mapped colour's spread over the footprint, fitted on docs/error_estimate/unseen.json (no shipped
// scene). With the tiling term (eq. 8: first order in the sub-footprints' size, so twice the difference from
// the tiling twice as fine) the two add in quadrature (eq. 9), scaled by kErrorScale, fitted on the same scene.
const float kErrorMismatch = 0.076;
const float kErrorScale = 0.44;

// |albedo - finer| per channel, 0 where it is within the float rounding of a mean of up to 8 x 4^2 taps
// (1e-5 of the colour): a footprint within one step of a step map is exact, and its two tilings' rounding
// would rank it among the erring pixels.
vec3 tiling_difference(vec3 albedo, vec3 finer) {
  vec3 d = abs(albedo - finer);
  return mix(d, vec3(0.0), lessThanEqual(d, 1e-5 * (1.0 + abs(albedo))));
}

// From the spread's and the tilings' radiance: eq. 9 where the dispatch compares tilings (GpuTile::list.z), else
// eq. 1 alone (filtered:adaptive's ranking).
float texture_error_term(vec3 spread, vec3 tilings) {
  float law = kErrorMismatch * (spread.r + spread.g + spread.b) / 3.0;
  if (tile.list.z == 0u) return law;
  float tiling = 2.0 * (tilings.r + tilings.g + tilings.b) / 3.0;
  return kErrorScale * sqrt(law * law + tiling * tiling);
}

vec3 camera_ray(vec2 film) {
  return camera_ray_direction(globals.camera_forward.xyz, globals.camera_right.xyz, globals.camera_up.xyz, film,
                              vec2(globals.image.xy));
}

// What the neighbouring pixel k (0: +x, 1: -x, 2: +y, 3: -y), `pixel_step` away on the film, sees of the hit's
// primitive: its camera ray d, and the point and unit normal there (surface_seen_by), the normal on the side of
// the pixel's own n. The corners of the pixel's parallelogram of normals and views, for the lobes and orders
// taken over the pixel.
struct Neighbour {
  vec3 d;
  vec3 p;
  vec3 n;
};

Neighbour neighbour_seen(Hit hit, vec3 p, vec3 n, vec3 o, vec2 film, float pixel_step, int k) {
  vec3 d_q = camera_ray(film + (k < 2 ? vec2(pixel_step, 0.0) : vec2(0.0, pixel_step)) * (k % 2 == 0 ? 1.0 : -1.0));
  SurfaceSeenBy q = surface_seen_by(hit, p, o, d_q);
  vec3 n_q = normalize(q.n);
  return Neighbour(d_q, q.p, dot(n_q, n) < 0.0 ? -n_q : n_q);
}

#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION)
// filtered averages `orders` over the pixel (docs/diffraction_fast_paths.md, "Orders over the pixel").
const bool kFiltersOrders = FACET_VARIANT_HAS(FACET_CODE_FILTERED) && FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_ORDERS) &&
                            kTextureMethod >= 3u && kDiffractionMethod == kDiffractionOrders;
#endif

#if FACET_VARIANT_HAS(FACET_CODE_FILTERED) && FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_ORDERS)
// The change of a grating's (u, v) = -(wi + wr)_xy per pixel step (xy along x, zw along y), eq. O1: the
// neighbouring camera rays' views in the frames (normal, tangent) the primitive shows them, on each axis the
// side where (u, v) changes less (smaller_pixel_step: a silhouette's outer side is not the pixel's). The
// neighbours take the pixel's side (`below`): one that grazes the silhouette sees the same face.
vec4 diffraction_pixel_uv_steps(Hit hit, vec3 p, vec3 n, bool below, vec3 o, vec3 d, vec3 l, vec2 film,
                                float pixel_step) {
  DiffractionDirections centre = diffraction_directions_seen(n, surface_uv(hit, p).dpdu, l, -d, below);
  vec2 uv = -(centre.wi.xy + centre.wr.xy);
  vec2 to[4];  // toward +x, -x, +y, -y
  for (int k = 0; k < 4; ++k) {
    Neighbour q = neighbour_seen(hit, p, n, o, film, pixel_step, k);
    DiffractionDirections w = diffraction_directions_seen(q.n, surface_uv(hit, q.p).dpdu, l, -q.d, below);
    to[k] = -(w.wi.xy + w.wr.xy) - uv;
  }
  return vec4(smaller_pixel_step(to[0], to[1]), smaller_pixel_step(to[2], to[3]));
}
#endif

// Radiance of the hit `hit` of the camera ray o + t d through `film` (pixels); `pixel_step` is the film
// distance to the neighbouring rays whose hits span the texture footprint.
vec3 shade(vec3 o, vec3 d, Hit hit, vec2 film, float pixel_step) {
  if (hit.material == kNoHit) return globals.background.rgb;
  vec3 p = o + hit.t * d;
  FacingNormal facing = facing_normal(hit, d);
  vec3 n = facing.n;
  bool back_face = facing.back_face;
  if (kWritesAovs) aov_depth_normal = vec4(hit.t * dot(d, globals.camera_forward.xyz), n);
  vec3 l = globals.light_direction.xyz;
  GpuMaterial m = material_at(hit.material);
  bool field_hit = false;
#ifdef FACET_HEIGHT_FIELDS
  MicrosurfaceFieldSample field;
  field_hit = kHasMicrosurface && hit.primitive == kHeightField;
  if (field_hit)
    field = microsurface_field_sample(m, hit, o, d, p, camera_ray(film + vec2(pixel_step, 0.0)),
                                      camera_ray(film + vec2(0.0, pixel_step)));
#endif
  // One call of occluded() casts every shadow ray (each call of the height-field traversal is compiled
  // on its own): the hit's own, and for a filtered field hit shaded partly by statistics (w < 1) a
  // second for the statistics, through the field from a footprint out (microsurface_field_radiance). The origin is
  // offset by a distance relative to the scene's scale at p; less from a traced field's hits, which are
  // exact to a few float ulps where the field's detail is finer than the macro-surfaces' offset.
  vec2 visibility = vec2(1.0);
  int rays = 1;
#if defined(FACET_HEIGHT_FIELDS) && FACET_VARIANT_HAS(FACET_CODE_FILTERED)
  if (field_hit && field.w < 1.0) rays = 2;
#endif
  for (int k = 0; k < rays; ++k) {
    Hit from = hit;
    vec3 from_n = n;
    float offset = field_hit ? 1e-5 : 1e-4;
    bool lit = dot(n, l) > 0.0;
    float field_skip = 0.0;
#ifdef FACET_HEIGHT_FIELDS
    lit = lit && (!field_hit || field.w > 0.0);  // a filtered hit shaded by statistics alone needs no ray
    if (k == 1) {  // Smith models the shadows of the detail within the footprint, this ray the rest's
      from = microsurface_flat_hit(hit, d);
      from_n = from.normal;
      offset = 1e-4;
      lit = dot(from_n, l) > 0.0;
      // The field within a footprint's width of the hit is the detail whose moments the statistics shade
      // (Smith covers its shadows): the ray meets the field from that far out, along the rectangle
      // (docs/microsurface_filtering.md, "Shadows beyond the footprint").
      float across = sqrt(max(1.0 - dot(from_n, l) * dot(from_n, l), 0.01));
      field_skip = microsurface_footprint_texels(field.fp) * m.albedo.w / across;
    }
#endif
    vec3 origin = p + from_n * (offset * max(1.0, length(p)));
    if (lit && occluded(origin, l, from, from_n, kTracesHeightFields, field_skip)) visibility[k] = 0.0;
  }
  if (kWritesAovs) aov_lit.x = visibility.x;
#ifdef FACET_HEIGHT_FIELDS
  if (field_hit) return microsurface_field_radiance(m, hit, field, d, n, l, visibility);
#endif
#if FACET_VARIANT_HAS(FACET_CODE_MICROSURFACE) && !defined(FACET_HEIGHT_FIELDS)  // traced, microsurfaces are hit as fields
  if (kHasMicrosurface && m.kind.x == FACET_MATERIAL_MICROSURFACE) {  // finite planes only (scene loader)
    GpuPlane plane = plane_at(hit.index);
    return microsurface_radiance(m, plane,
                                 microsurface_footprint(m, plane, o, d, p, camera_ray(film + vec2(pixel_step, 0.0)),
                                                        camera_ray(film + vec2(0.0, pixel_step)), plane.normal.xyz),
                                 d, l, visibility.x, false);
  }
#endif
#if FACET_VARIANT_HAS(FACET_CODE_MICROFLAKE)
  if (kHasMicroflake && m.kind.x == FACET_MATERIAL_MICROFLAKE) {
#if FACET_VARIANT_HAS(FACET_CODE_FILTERED)
    // filtered averages the lobe over the pixel (docs/microflake_brdf.md, "The lobe over the pixel"), whose
    // normals and views turn toward the neighbouring rays' (F3), on each axis the side where they turn less.
    vec4 steps = vec4(0.0);
    if (kTextureMethod >= 3u) {
      vec2 to[4];  // toward +x, -x, +y, -y
      vec2 centre = microflake_frame_slope(n, l - d);
      for (int k = 0; k < 4; ++k) {
        Neighbour q = neighbour_seen(hit, p, n, o, film, pixel_step, k);
        to[k] = microflake_half_slope_step(n, l, centre, q.n, -q.d);
      }
      steps = vec4(smaller_pixel_step(to[0], to[1]), smaller_pixel_step(to[2], to[3]));
    }
    return microflake_radiance_over_pixel(int(m.kind.y), m.params.x, m.albedo.rgb, n, -d, l,
                                          globals.light_irradiance.rgb, visibility.x, globals.ambient.rgb, steps);
#else
    return microflake_radiance(int(m.kind.y), m.params.x, m.albedo.rgb, n, -d, l, globals.light_irradiance.rgb,
                               visibility.x, globals.ambient.rgb);
#endif
  }
#endif
  vec3 albedo = m.albedo.rgb;
#if FACET_VARIANT_HAS(FACET_CODE_TEXTURE)
  if (kHasTexture && m.kind.x == FACET_MATERIAL_COLORMAP_TEXTURE) {
    SurfaceUv s = surface_uv(hit, p);
    vec2 duv_dx = vec2(0.0), duv_dy = vec2(0.0);
    if (kTextureMethod != 0u) {
      duv_dx = uv_differential(o, camera_ray(film + vec2(pixel_step, 0.0)), p, n, s.dpdu, s.dpdv);
      duv_dy = uv_differential(o, camera_ray(film + vec2(0.0, pixel_step)), p, n, s.dpdu, s.dpdv);
    }
    vec3 spread, finer;
    albedo = textured_albedo(m, s.uv, duv_dx, duv_dy, spread, finer);
    if (kWritesAovs) {  // the texture term (eq. 9): the law's (eq. 1) and the tiling's (eq. 8), as radiance
      vec3 e_law = lambert_radiance(spread, n, l, globals.light_irradiance.rgb, visibility.x, globals.ambient.rgb);
      vec3 e_tiling = lambert_radiance(tiling_difference(albedo, finer), n, l, globals.light_irradiance.rgb, visibility.x,
                                       globals.ambient.rgb);
      aov_uv_error.z = texture_error_term(e_law, e_tiling);
      aov_uv_error.w = 1.0;  // the texture term models this hit (eq. 3' leaves it alone)
    }
  }
#endif
  vec3 diffracted = vec3(0.0);  // a diffraction material's albedo is its Lambertian base
#if FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION)
  if (kHasDiffraction && m.kind.x == FACET_MATERIAL_DIFFRACTION) {
    vec4 uv_steps = vec4(0.0);
#if FACET_VARIANT_HAS(FACET_CODE_FILTERED) && FACET_VARIANT_HAS(FACET_CODE_DIFFRACTION_ORDERS)
    if (kFiltersOrders) uv_steps = diffraction_pixel_uv_steps(hit, p, n, back_face, o, d, l, film, pixel_step);
#endif
    diffracted = diffraction_shading(m.kind.y, n, back_face, surface_uv(hit, p).dpdu, -d, l, visibility.x, kFiltersOrders,
                                     uv_steps);
  }
#endif
  return lambert_radiance(albedo, n, l, globals.light_irradiance.rgb, visibility.x, globals.ambient.rgb) + diffracted;
}

// Radiance along the camera ray through `film` (rgb), and 1 if it hit geometry, 0 if not (a: coverage).
vec4 radiance(vec2 film, float pixel_step) {
  vec3 o = globals.camera_origin.xyz;
  vec3 d = camera_ray(film);
  Hit hit = trace(o, d, 0.0, kInfinity, kTracesHeightFields);
  if (kWritesAovs && hit.material != kNoHit) {
    // uv of macro-surfaces; a microsurface's hits keep 0 (its field has texel coordinates of its own).
    if (material_at(hit.material).kind.x != FACET_MATERIAL_MICROSURFACE)
      aov_uv_error.xy = surface_uv(hit, o + hit.t * d).uv;
  }
  return vec4(shade(o, d, hit, film, pixel_step), hit.material == kNoHit ? 0.0 : 1.0);
}

// filtered:adaptive's refinement renders listed strata of pixels (tile.list.x > 0) anywhere in the frame.
layout(binding = FACET_RENDER_BINDING_PIXEL_LIST) uniform usamplerBuffer pixel_list;

// This invocation's workgroup's block: block g s mod n of the n blocks (g: the workgroup's index in
// the dispatch), so each lavapipe thread's contiguous share of the workgroups is spread over the whole
// tile or list (renderer/gpu/workgroup_order.hpp).
uint spread_block() {
  uint g = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  return (g * tile.spread.y) % tile.spread.x;
}

// The tile position of this invocation.
uvec2 tile_position() {
  uint block = spread_block();
  return uvec2(block % gl_NumWorkGroups.x, block / gl_NumWorkGroups.x) * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy;
}

// The sample in slot i of the pixel buffer: its pixel (xy) and stratum (zw). A tile's slot is its pixel's
// position in the tile; a listed slot is one stratum of a pixel, (x | stratum << 16, y) in the pixel list.
uvec4 slot_sample(uint i) {
  uint k = tile.stratum.w;
  if (tile.list.x != 0u) {
    uvec2 entry = texelFetch(pixel_list, int(i)).xy;
    return uvec4(entry.x & 0xffffu, entry.y, (entry.x >> 16u) % k, (entry.x >> 16u) / k);
  }
  return uvec4(uvec2(i % tile.rect.z, i / tile.rect.z) + tile.rect.xy, tile.stratum.xy);
}

// The film position of a sample (slot_sample) of K x K strata.
vec2 sample_film(uvec4 sample_at, float step) { return vec2(sample_at.xy) + (vec2(sample_at.zw) + 0.5) * step; }

// Whether a sample's stored sum is the pixel's last: a tile's last stratum scales the sum of its strata (a listed
// entry keeps its own sample, which the host adds up; work is a sum).
bool scales_pixel() { return tile.list.x == 0u && tile.stratum.z == tile.stratum.w * tile.stratum.w - 1u && !kCountsWork; }

#if defined(FACET_HEIGHT_FIELDS) && FACET_VARIANT_HAS(FACET_CODE_FILTERED)
// kStatisticsPass: entry e of the queue (GpuTile::list.w entries, from the tracing dispatch of the same tile and
// stratum) adds the statistics' part of its sample to the sample's slot, from the same camera ray and hit as
// the tracing pass's, scaled as main() scales a tile's last stratum (which left a queued sample's scaling here).
void shade_queued_statistics() {
  uint e = spread_block() * gl_WorkGroupSize.x * gl_WorkGroupSize.y + gl_LocalInvocationIndex;
  if (e >= tile.list.w) return;
  QueuedStatistics q = queued_statistics(e);
  uint k = tile.stratum.w;
  float step = 1.0 / float(k);
  vec2 film = sample_film(slot_sample(q.slot), step);
  vec3 o = globals.camera_origin.xyz, d = camera_ray(film);
  GpuPlane plane = plane_at(q.plane);
  Hit hit = Hit(q.t, plane.normal.xyz, plane.material.x, kHeightField, q.plane, vec2(0.0));
  GpuMaterial m = material_at(hit.material);
  MicrosurfaceFieldSample s = microsurface_field_sample(m, hit, o, d, o + q.t * d, camera_ray(film + vec2(step, 0.0)),
                                                        camera_ray(film + vec2(0.0, step)));
  vec4 value = vec4(microsurface_field_statistics(m, hit, s, d, globals.light_direction.xyz, q.visibility), 0.0);
  if (kCountsWork) value = vec4(float(facet_work_fma), float(facet_work_reads), 0.0, 0.0);
  vec4 sum = pixels[q.slot] + value;
  pixels[q.slot] = scales_pixel() ? sum / float(k * k) : sum;
}
#endif

void main() {
#if defined(FACET_HEIGHT_FIELDS) && FACET_VARIANT_HAS(FACET_CODE_FILTERED)
  if (kStatisticsPass) {
    shade_queued_statistics();
    return;
  }
#endif
  uint i;  // the sample's slot in the pixel buffer
  uint k = tile.stratum.w;
  bool listed = tile.list.x != 0u;
  if (listed) {
    i = spread_block() * gl_WorkGroupSize.x * gl_WorkGroupSize.y + gl_LocalInvocationIndex;
    if (i >= tile.list.x) return;
  } else {
    uvec2 at = tile_position();
    if (at.x >= tile.rect.z || at.y >= tile.rect.w) return;
    i = at.y * tile.rect.z + at.x;
  }
  float step = 1.0 / float(k);
  vec4 sample_value = radiance(sample_film(slot_sample(i), step), step);
  if (kCountsWork) sample_value = vec4(float(facet_work_fma), float(facet_work_reads), 0.0, 1.0);
  // A tile's strata add up here, one dispatch each, in the order of a loop over sy, then sx, and the sum
  // is scaled once at the end: the same float operations as averaging them within one invocation. A listed
  // entry keeps its own sample, which the host adds up in the same order (DirectPass::refine).
  bool adds = !listed && tile.stratum.z != 0u;
  vec4 sum = adds ? pixels[i] + sample_value : sample_value;
  // Work adds up over the strata: a pixel's work is their sum (renderer/gpu/work_per_pixel.cpp).
  bool queued = false;  // the statistics' dispatch adds the rest of the sample, and scales it
#if defined(FACET_HEIGHT_FIELDS) && FACET_VARIANT_HAS(FACET_CODE_FILTERED)
  queued = statistics_pending;
  if (queued) {
    pending_statistics.slot = i;
    queue_statistics(pending_statistics);
  }
#endif
  pixels[i] = scales_pixel() && !queued ? sum / float(k * k) : sum;
  if (kWritesAovs) {  // sums over the strata, divided on the host by the hits (the error by k^2)
    uint n = tile.rect.z * tile.rect.w;  // a list's length for a list (rect = (0, 0, n, 1))
    pixels[n + i] = adds ? pixels[n + i] + aov_depth_normal : aov_depth_normal;
    pixels[2u * n + i] = adds ? pixels[2u * n + i] + aov_uv_error : aov_uv_error;
    pixels[3u * n + i] = adds ? pixels[3u * n + i] + aov_lit : aov_lit;
  }
}

#endif
