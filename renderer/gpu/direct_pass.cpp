#include "gpu/direct_pass.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "common/error.hpp"
#include "gpu/adaptive_refinement.hpp"
#include "gpu/direct_pass_variant.hpp"
#include "gpu/heightfield_trace_bound.hpp"
#include "gpu/pixel_coverage.hpp"
#include "gpu/render_layout.hpp"
#include "gpu/texture_upload.hpp"
#include "gpu/work_counter.hpp"
#include "gpu/workgroup_order.hpp"
#include "image/edge_error.hpp"

namespace facet::gpu {

namespace {
// A tile's workgroups, numbered by 32-bit products in the shader's tile_position, stay within its bound.
static_assert((kMaxTileSize / FACET_RENDER_WORKGROUP) * (kMaxTileSize / FACET_RENDER_WORKGROUP) <= kMaxTileBlocks);

// The program of the pass: the smallest variant that compiles in `code` (the plan's: gpu/direct_pass_variant.hpp).
// Counting work, the program with its counters' increments (gpu/work_counter.hpp).
std::vector<uint32_t> direct_pass_program(const Scene& scene, const RenderMethod& method, uint32_t code) {
  const std::span<const uint32_t> program = direct_pass_variant(code, traces_height_fields(scene, method)).spirv;
  return method.counts_work ? instrument_work_counts(program) : std::vector<uint32_t>(program.begin(), program.end());
}

// The shadow rays a sample casts through height fields: one, and filtered's statistics' ray from a footprint
// out (T5); 0 where the method traces none.
int field_shadow_rays(const Scene& scene, const RenderMethod& method) {
  if (!traces_height_fields(scene, method)) return 0;
  return method.texture >= RenderMethod::Texture::Filtered ? 2 : 1;
}

// The one-line refusal of a sample's rays through height fields that could pass the tracer's loop bound
// (render/heightfield_trace.glsl; lavapipe would cut the loop short without a word): its camera ray's nodes (0
// where no camera is known yet: `any_camera` says so) and `shadow_rays` shadow rays' of `shadow_nodes` each.
void check_traversal(std::int64_t camera_nodes, int shadow_rays, std::int64_t shadow_nodes, const std::string& method,
                     bool any_camera) {
  const std::int64_t longest = std::max(camera_nodes, shadow_nodes), sample = camera_nodes + shadow_rays * shadow_nodes;
  const std::string rays = "(camera ray " + std::to_string(camera_nodes) + ", " + std::to_string(shadow_rays) +
                           " shadow ray" + (shadow_rays > 1 ? "s" : "") + " of " + std::to_string(shadow_nodes) + ")";
  const std::string passed = longest > FACET_HEIGHTFIELD_MAX_STEPS
                                 ? "a ray may visit " + std::to_string(longest) + " MIP nodes " + rays +
                                       ", more than its loop bound of " + std::to_string(FACET_HEIGHTFIELD_MAX_STEPS)
                             : sample > FACET_HEIGHTFIELD_SAMPLE_STEPS
                                 ? "a sample's rays may visit " + std::to_string(sample) + " MIP nodes " + rays +
                                       ", more than their loop bound of " +
                                       std::to_string(FACET_HEIGHTFIELD_SAMPLE_STEPS)
                                 : "";
  if (!passed.empty())
    throw Error(
        "the microsurfaces' height fields span too many texels for the GPU tracer: " + passed + " for " + method +
        (any_camera ? " whatever the camera" : "") +
        " (use coarser texels, a smaller rectangle, a light or camera farther above the field, or --method mip)");
}

// Whether the pass accumulates the auxiliary values: asked for, or filtered:adaptive's error estimate.
bool writes_aovs(const RenderMethod& method) { return method.aovs.any() || method.adaptive_samples_per_axis > 0; }

// Whether a dispatch computes the texture's error estimate: for the frame's error channel, and in
// filtered:adaptive's first pass, which ranks by it (a refinement's goes only to the channel, if any).
bool computes_estimate(bool error_channel, bool adaptive, bool refining) {
  return error_channel || (adaptive && !refining);
}

// Whether the estimate takes its tiling term (docs/error_estimate.md, eq. 8: a second tiling of every footprint,
// four times the first's taps): for the error channel of a frame rendered in one pass. filtered:adaptive's plan
// ranks by the estimate without it: at equal device time its refinements remove more error than the term's
// better ranking does.
bool compares_tilings(bool error_channel, bool adaptive) { return error_channel && !adaptive; }

// The points of the scene's longest colour map of this interpolation on a colour-mapped texture (0: none).
std::size_t longest_texture_colormap(const Scene& scene, Colormap::Interpolation interpolation) {
  std::size_t longest = 0;
  for (const Material& m : scene.materials)
    if (const auto* t = std::get_if<ColormapTextureMaterial>(&m); t && t->colormap.interpolation() == interpolation)
      longest = std::max(longest, t->colormap.positions().size());
  return longest;
}

// Whether a colour-mapped texture of the scene has a map of this interpolation.
uint32_t uses_colormaps(const Scene& scene, Colormap::Interpolation interpolation) {
  return longest_texture_colormap(scene, interpolation) > 0 ? 1u : 0u;
}

// The longest such map's points if it has at most FACET_RENDER_WALKED_COLORMAP_POINTS, else 0 (also without
// any): the shader's walks over a map's points are then unrolled to that many trips (render/texture_sampling.glsl).
uint32_t unrolled_colormap_points(const Scene& scene, Colormap::Interpolation interpolation) {
  const std::size_t longest = longest_texture_colormap(scene, interpolation);
  return longest <= FACET_RENDER_WALKED_COLORMAP_POINTS ? static_cast<uint32_t>(longest) : 0u;
}

// Every colour map colormap_at may look up: the textures' and the microsurfaces'.
template <typename Visit>
void for_each_colormap(const Scene& scene, Visit visit) {
  for (const Material& m : scene.materials) {
    if (const auto* t = std::get_if<ColormapTextureMaterial>(&m)) visit(t->colormap);
    if (const auto* s = std::get_if<MicrosurfaceMaterial>(&m)) {
      if (s->height_colormap) visit(*s->height_colormap);
      if (s->slope_colormap) visit(*s->slope_colormap);
    }
  }
}

// The trips of colormap_at's bisection over the scene's colour maps, n >= 2 points: the interval j - i = n - 1
// falls to at most ceil((j - i) / 2) a trip, so ceil(log2(n - 1)) = bit_width(n - 2) trips end it; a map searched
// from a division starts from 3 segments (bit_width(2) = 2 trips, render/texture_sampling.glsl). The shader
// unrolls the search to the most any map needs.
uint32_t colormap_search_steps(const Scene& scene) {
  std::size_t longest = 2;  // the points of the longest search: 4 for a map searched from a division
  for_each_colormap(scene, [&longest](const Colormap& map) {
    longest = std::max<std::size_t>(longest, colormap_searched_by_division(map) ? 4 : map.positions().size());
  });
  return static_cast<uint32_t>(std::bit_width(longest - 2));
}

// Whether some colour map of the scene is searched from a division (kColormapDivides: else its code is left out).
uint32_t colormaps_divide(const Scene& scene) {
  bool divides = false;
  for_each_colormap(scene,
                    [&divides](const Colormap& map) { divides = divides || colormap_searched_by_division(map); });
  return divides ? 1u : 0u;
}

// The trips of the shader's loops over the scene's planes or spheres (render/trace.glsl): their count where
// there are at most four, so the loops unroll, else FACET_RENDER_LOOPED_TRIPS. The height-field program
// unrolls a single plane only: each unrolled plane inlines the field traversal once more, and lavapipe's
// pipeline set-up grows with the inlined code. Scenes with meshes keep the loops: there the unrolled
// closest-hit loop made the BVH traversal after it slower (colormap_seams_cube `filtered` 1.3-1.7x the
// device time; docs/render_speed.md, "Loops on lavapipe").
uint32_t primitive_trips(const Scene& scene, const RenderMethod& method, std::size_t count) {
  const std::size_t unrolled_at_most = !scene.meshes.empty() ? 0 : traces_height_fields(scene, method) ? 1 : 4;
  return count <= unrolled_at_most ? static_cast<uint32_t>(count) : FACET_RENDER_LOOPED_TRIPS;
}

// Whether a microsurface of the scene has this part (height or slope colour map, specular lobe).
template <typename Part>
bool some_microsurface_has(const Scene& scene, Part part) {
  for (const Material& m : scene.materials)
    if (const auto* s = std::get_if<MicrosurfaceMaterial>(&m); s && ((*s).*part).has_value()) return true;
  return false;
}

// Whether every MIP chain the pass looks up bilinearly (colour-mapped textures, a microsurface's box-filtered
// chains) has whole texels on every level: level-0 sizes that are powers of two (mip_chain_sizes halves
// them to 1 x 1), so the shader may take lib/mip_grid.glsl's shortcut.
bool mip_texels_are_whole(const Scene& scene) {
  const auto whole = [](const assets::ScalarField& field) {
    return std::has_single_bit(static_cast<unsigned>(field.width)) &&
           std::has_single_bit(static_cast<unsigned>(field.height));
  };
  for (const Material& m : scene.materials) {
    if (const auto* t = std::get_if<ColormapTextureMaterial>(&m); t && !whole(*t->texture)) return false;
    if (const auto* s = std::get_if<MicrosurfaceMaterial>(&m); s && !whole(*s->heights)) return false;
  }
  return true;
}

// The specialization constants of the pass by their names in the shaders: what the scene uses (`code`, the
// plan's), how the method shades it. One entry per named id (the count is checked; render_layout.hpp checks the ids).
std::vector<vk::SpecConstant> specialization(const Scene& scene, const RenderMethod& method,
                                             const DiffractionPlan& diffraction, uint32_t code, bool statistics_pass) {
  const auto has = [code](uint32_t part) { return (code & part) != 0 ? 1u : 0u; };
  const auto constants = std::to_array<vk::SpecConstant>({
      {FACET_RENDER_SPEC_HAS_MICROFLAKE, has(FACET_CODE_MICROFLAKE)},
      {FACET_RENDER_SPEC_HAS_TEXTURE, has(FACET_CODE_TEXTURE)},
      {FACET_RENDER_SPEC_TEXTURE_METHOD, static_cast<uint32_t>(method.texture)},
      {FACET_RENDER_SPEC_HAS_DIFFRACTION, has(FACET_CODE_DIFFRACTION)},
      {FACET_RENDER_SPEC_DIFFRACTION_METHOD, static_cast<uint32_t>(diffraction.method)},
      {FACET_RENDER_SPEC_HAS_MICROSURFACE, has(FACET_CODE_MICROSURFACE)},
      {FACET_RENDER_SPEC_HAS_SPHERES, has(FACET_CODE_SPHERES)},
      {FACET_RENDER_SPEC_HAS_TRIANGLES, has(FACET_CODE_TRIANGLES)},
      {FACET_RENDER_SPEC_PREINTEGRATED_SLICES, diffraction.preintegrated_slices.count},
      {FACET_RENDER_SPEC_PREINTEGRATED_SLICE_WORDS, diffraction.preintegrated_slices.slice_words},
      {FACET_RENDER_SPEC_AOVS, writes_aovs(method) ? 1u : 0u},
      {FACET_RENDER_SPEC_COUNTS_WORK, method.counts_work ? 1u : 0u},
      {FACET_RENDER_SPEC_HAS_LINEAR_COLORMAPS, uses_colormaps(scene, Colormap::Interpolation::Linear)},
      {FACET_RENDER_SPEC_HAS_STEP_COLORMAPS, uses_colormaps(scene, Colormap::Interpolation::Steps)},
      {FACET_RENDER_SPEC_WHOLE_MIP_TEXELS, mip_texels_are_whole(scene) ? 1u : 0u},
      // Some dispatch computes the estimate (a first pass, if any does); without, its code is left out of the
      // pipeline, for lavapipe would run it masked on every tap.
      {FACET_RENDER_SPEC_ESTIMATES_ERROR,
       computes_estimate(method.aovs.error, method.adaptive_samples_per_axis > 0, false) ? 1u : 0u},
      {FACET_RENDER_SPEC_MICROSURFACE_HEIGHT_MAPS,
       some_microsurface_has(scene, &MicrosurfaceMaterial::height_colormap) ? 1u : 0u},
      {FACET_RENDER_SPEC_MICROSURFACE_SLOPE_MAPS,
       some_microsurface_has(scene, &MicrosurfaceMaterial::slope_colormap) ? 1u : 0u},
      {FACET_RENDER_SPEC_MICROSURFACE_LOBES, some_microsurface_has(scene, &MicrosurfaceMaterial::specular) ? 1u : 0u},
      {FACET_RENDER_SPEC_STEP_COLORMAP_POINTS, unrolled_colormap_points(scene, Colormap::Interpolation::Steps)},
      {FACET_RENDER_SPEC_LINEAR_COLORMAP_POINTS, unrolled_colormap_points(scene, Colormap::Interpolation::Linear)},
      {FACET_RENDER_SPEC_COLORMAP_SEARCH_STEPS, colormap_search_steps(scene)},
      {FACET_RENDER_SPEC_COLORMAP_DIVIDES, colormaps_divide(scene)},
      {FACET_RENDER_SPEC_PLANE_TRIPS, primitive_trips(scene, method, scene.planes.size())},
      {FACET_RENDER_SPEC_SPHERE_TRIPS, primitive_trips(scene, method, scene.spheres.size())},
      {FACET_RENDER_SPEC_STATISTICS_PASS, statistics_pass ? 1u : 0u},
  });
  static_assert(std::tuple_size_v<decltype(constants)> == FACET_RENDER_SPEC_COUNT);
  return {constants.begin(), constants.end()};
}

// The scene's bindings (SceneBuffers::binding_kinds), then the diffraction buffers, read in the
// per-wavelength loops, as texel buffers (render/diffraction_bindings.glsl).
std::vector<vk::BufferKind> binding_kinds() {
  std::vector<vk::BufferKind> kinds = SceneBuffers::binding_kinds();
  kinds.resize(FACET_RENDER_BINDING_COUNT, vk::BufferKind::Texels);
  kinds[FACET_RENDER_BINDING_STATISTICS_QUEUE] = vk::BufferKind::Storage;
  return kinds;
}

// The pass's pipeline for `spec`, compiled on a thread of its own (lavapipe's pipeline creation is CPU work of its
// own) while the diffraction tables are read and the textures upload. The thread ends before the pass's
// constructor does (the kernels wait for it; so does the future if the reading or the upload throws).
std::future<std::unique_ptr<vk::Kernel>> compile(vk::Context& context, const Scene& scene, const RenderMethod& method,
                                                 std::vector<vk::SpecConstant> spec, uint32_t code) {
  return std::async(std::launch::async, [&context, &scene, &method, spec = std::move(spec), code] {
    const std::vector<uint32_t> program = direct_pass_program(scene, method, code);
    return std::make_unique<vk::Kernel>(context, vk::KernelDesc{.name = "render_direct",
                                                                .spirv = program,
                                                                .buffer_count = FACET_RENDER_BINDING_COUNT,
                                                                .push_constant_bytes = sizeof(GpuTile),
                                                                .specialization = spec,
                                                                .buffer_kinds = binding_kinds()});
  });
}

// Whether filtered's microsurface statistics are shaded in a dispatch of their own
// (render/microsurface_statistics_queue.glsl): wherever the pass traces height fields for filtered.
bool queues_statistics(const Scene& scene, const RenderMethod& method, uint32_t code) {
  return traces_height_fields(scene, method) && (code & FACET_CODE_FILTERED) != 0 &&
         (code & FACET_CODE_MICROSURFACE) != 0;
}

// The statistics queue's bytes for `entries` (render/microsurface_statistics_queue.glsl): a uvec4 count, then a
// uvec4 an entry, and a workgroup's more, which the last workgroup's masked lanes read.
uint64_t statistics_queue_bytes(int entries) {
  return sizeof(glm::uvec4) * (1 + static_cast<uint64_t>(entries) + FACET_RENDER_WORKGROUP * FACET_RENDER_WORKGROUP);
}

// A pixel's planes in the pixel buffer (render/direct_pass.glsl): the colour and coverage, then, with
// auxiliary outputs, the sums over the strata of (depth, normal), (uv, error, texture term) and (lit, -).
constexpr std::size_t kPixelPlanes = 4;
using PixelPlanes = std::array<vec4, kPixelPlanes>;

// The vec4s per pixel of the pixel buffer.
uint64_t pixel_vec4s(bool writes_aovs) { return writes_aovs ? kPixelPlanes : 1; }

// The planes of the pixel at `i` of a buffer of `n` pixels per plane.
PixelPlanes pixel_planes(const std::vector<vec4>& buffer, std::size_t i, std::size_t n) {
  PixelPlanes planes;
  for (std::size_t plane = 0; plane < kPixelPlanes; ++plane) planes[plane] = buffer[plane * n + i];
  return planes;
}

// One pixel's auxiliary outputs from their sums over k^2 strata, `hits` of which hit geometry:
// depth, normal, uv and the lit fraction are means over the hits (the normal renormalised), the error
// over all strata.
AovPixel aov_pixel(const PixelPlanes& sums, float hits, int k) {
  const vec4 depth_normal = sums[1], uv_error = sums[2], lit = sums[3];
  AovPixel p;
  p.depth = hits > 0.0f ? depth_normal.x / hits : std::numeric_limits<float>::infinity();
  const glm::vec3 normal(depth_normal.y, depth_normal.z, depth_normal.w);
  if (hits > 0.0f) {
    if (glm::dot(normal, normal) > 0.0f) p.normal = glm::normalize(normal);
    p.uv = glm::vec2(uv_error.x, uv_error.y) / hits;
    p.lit = lit.x / hits;
  }
  p.error = uv_error.z / static_cast<float>(k * k);
  p.texture_term = uv_error.w > 0.0f;
  return p;
}

// What the pass writes for a pixel all of whose k^2 strata miss (render/direct_pass.glsl, main): the
// background, its strata added in order and the sum divided once, coverage 0; its auxiliary sums are 0.
vec4 missed_pixel(glm::dvec3 background, int k) {
  const vec4 sample(glm::vec3(background), 0.0f);
  vec4 sum = sample;
  for (int s = 1; s < k * k; ++s) sum = sum + sample;
  return sum / static_cast<float>(k * k);
}

}  // namespace

int tile_count(int width, int height, int tile_size) {
  return ((width + tile_size - 1) / tile_size) * ((height + tile_size - 1) / tile_size);
}

// A still's camera ray is checked with the shadow rays; a camera path's frames as they render.
DirectPass::Plan DirectPass::make_plan(vk::Context& context, const Scene& scene, const RenderMethod& method) {
  Plan plan;
  plan.field_shadow_rays = field_shadow_rays(scene, method);
  if (plan.field_shadow_rays > 0) {
    plan.field_shadow_nodes = heightfield_shadow_nodes(scene);
    check_traversal(scene.camera_path ? 0 : heightfield_camera_nodes(scene, scene.camera.position),
                    plan.field_shadow_rays, plan.field_shadow_nodes, method.name(), scene.camera_path.has_value());
  }
  plan.diffraction = plan_diffraction(context, scene, method.pass_diffraction());
  plan.code = direct_pass_code(scene, method, orders_fall_back(plan.diffraction));
  return plan;
}

DirectPass::DirectPass(vk::Context& context, const Scene& scene, const RenderMethod& method, int tile_size,
                       PhaseTimings* timings)
    : DirectPass(context, scene, method, tile_size, timings,
                 timed(timings, "diffraction", [&] { return make_plan(context, scene, method); })) {}

DirectPass::DirectPass(vk::Context& context, const Scene& scene, const RenderMethod& method, int tile_size,
                       PhaseTimings* timings, Plan plan)
    : scene_(&scene),
      bounds_(scene),
      method_name_(method.name()),
      field_shadow_rays_(plan.field_shadow_rays),
      field_shadow_nodes_(plan.field_shadow_nodes),
      tile_size_(tile_size > 0 && tile_size <= kMaxTileSize
                     ? tile_size
                     : throw Error("tile size must lie in 1.." + std::to_string(kMaxTileSize))),
      samples_per_axis_(method.samples_per_axis),
      aovs_(method.aovs),
      adaptive_samples_per_axis_(method.adaptive_samples_per_axis),
      adaptive_budget_(method.adaptive),
      writes_aovs_(writes_aovs(method)),
      counts_work_(method.counts_work),
      // The specialization needs the diffraction's plan (method, the tables' layout), not their words nor
      // anything of the textures.
      compiling_(compile(context, scene, method, specialization(scene, method, plan.diffraction, plan.code, false),
                         plan.code)),
      compiling_statistics_(queues_statistics(scene, method, plan.code)
                                ? compile(context, scene, method,
                                          specialization(scene, method, plan.diffraction, plan.code, true), plan.code)
                                : std::future<std::unique_ptr<vk::Kernel>>()),
      // The tables' words (the table cache's file, or their build), read while the pipeline compiles.
      diffraction_(
          timed(timings, "diffraction", [&] { return upload_diffraction(context, std::move(plan.diffraction)); })),
      buffers_(
          timed(timings, "upload",
                [&] { return upload_scene(context, scene, method.texture == RenderMethod::Texture::FilteredTable); })),
      // filtered:adaptive: a tile's worth of strata a dispatch, and at least one pixel's.
      list_capacity_(
          method.adaptive_samples_per_axis > 0
              ? std::max(tile_size_ * tile_size_, method.adaptive_samples_per_axis * method.adaptive_samples_per_axis)
              : 1),
      pixels_(context, sizeof(vec4) * pixel_vec4s(writes_aovs_) *
                           static_cast<uint64_t>(std::max(tile_size_ * tile_size_, list_capacity_))),
      pixel_list_(vk::Buffer::of<glm::uvec2>(context, static_cast<size_t>(list_capacity_))),
      statistics_queue_(context, statistics_queue_bytes(compiling_statistics_.valid()
                                                            ? std::max(tile_size_ * tile_size_, list_capacity_)
                                                            : 1)),
      // The part of the pipelines' creation the upload did not hide.
      kernel_(timed(timings, "pipeline", [&] {
        if (compiling_statistics_.valid()) statistics_kernel_ = compiling_statistics_.get();
        return compiling_.get();
      })) {
  // The statistics' dispatch may read entries its lanes do not shade (lavapipe runs masked lanes): zeros.
  const std::vector<char> zeros(statistics_queue_.size(), 0);
  statistics_queue_.upload(zeros.data(), zeros.size());
  // lavapipe JIT-compiles a pipeline on its first dispatch: one pixel here keeps that out of every
  // frame's device time (and gives it a phase of its own).
  timed(timings, "jit", [&] {
    buffers_.set_camera(scene, scene.camera, 1, 1);
    dispatch_tile(bindings(), 0, 0, 1, 1, 0);
    if (statistics_kernel_) {  // an empty queue: one workgroup of masked lanes
      const GpuTile empty{uvec4(0, 0, 1, 1), uvec4(0, 0, 0, 1), uvec4(1, 1, 0, 0), uvec4(0, 1, 0, 0)};
      statistics_kernel_->dispatch(bindings(), &empty, glm::uvec3(1, 1, 1));
    }
  });
}

double DirectPass::dispatch(std::span<const vk::Buffer* const> bindings, GpuTile tile, glm::uvec3 groups) {
  if (!statistics_kernel_) return kernel_->dispatch(bindings, &tile, groups);
  const uint32_t none = 0;
  statistics_queue_.upload(&none, sizeof none);
  double ms = kernel_->dispatch(bindings, &tile, groups);
  uint32_t queued = 0;
  statistics_queue_.download(&queued, sizeof queued);
  if (queued == 0) return ms;
  constexpr uint32_t kGroup = FACET_RENDER_WORKGROUP * FACET_RENDER_WORKGROUP;
  const uint32_t blocks = (queued + kGroup - 1) / kGroup;
  tile.spread = uvec4(blocks, workgroup_spread_stride(blocks), 0, 0);
  tile.list.w = queued;
  return ms + statistics_kernel_->dispatch(bindings, &tile, glm::uvec3(blocks, 1, 1));
}

double DirectPass::dispatch_tile(std::span<const vk::Buffer* const> bindings, int x0, int y0, int w, int h,
                                 int stratum) {
  const glm::uvec3 groups((w + FACET_RENDER_WORKGROUP - 1) / FACET_RENDER_WORKGROUP,
                          (h + FACET_RENDER_WORKGROUP - 1) / FACET_RENDER_WORKGROUP, 1);
  const uint32_t blocks = groups.x * groups.y;
  const uvec4 spread(blocks, workgroup_spread_stride(blocks), 0, 0);
  const int k = samples_per_axis_;
  const GpuTile tile{uvec4(x0, y0, w, h), uvec4(stratum % k, stratum / k, stratum, k), spread,
                     uvec4(0, skips_estimate(false), compares_tilings(aovs_.error, adaptive_samples_per_axis_ > 0), 0)};
  return dispatch(bindings, tile, groups);
}

double DirectPass::dispatch_list(std::span<const vk::Buffer* const> bindings, std::size_t count, int k) {
  constexpr uint32_t kGroup = FACET_RENDER_WORKGROUP * FACET_RENDER_WORKGROUP;
  const uint32_t blocks = static_cast<uint32_t>((count + kGroup - 1) / kGroup);
  const uvec4 spread(blocks, workgroup_spread_stride(blocks), 0, 0);
  const auto n = static_cast<uint32_t>(count);
  const GpuTile tile{uvec4(0, 0, n, 1), uvec4(0, 0, 0, k), spread, uvec4(n, skips_estimate(true), 0, 0)};
  return dispatch(bindings, tile, glm::uvec3(blocks, 1, 1));
}

uint32_t DirectPass::skips_estimate(bool refining) const {
  return computes_estimate(aovs_.error, adaptive_samples_per_axis_ > 0, refining) ? 0u : 1u;
}

double DirectPass::refine_group(std::span<const vk::Buffer* const> bindings, std::span<const uint32_t> pixels, int k,
                                Image& image, std::vector<AovPixel>& aovs, std::span<const float> edge) {
  const size_t strata = static_cast<size_t>(k) * k, per_dispatch = static_cast<size_t>(list_capacity_) / strata;
  std::vector<glm::uvec2> entries;
  std::vector<vec4> samples;
  double ms = 0.0;
  for (size_t begin = 0; begin < pixels.size(); begin += per_dispatch) {
    const std::span<const uint32_t> chunk = pixels.subspan(begin, std::min(per_dispatch, pixels.size() - begin));
    const size_t n = chunk.size() * strata;
    entries.resize(n);
    for (size_t j = 0; j < chunk.size(); ++j)
      for (size_t s = 0; s < strata; ++s)  // (x | stratum << 16, y): widths are at most 16384, K^2 at most 256
        entries[j * strata + s] =
            glm::uvec2(chunk[j] % static_cast<uint32_t>(image.width) | static_cast<uint32_t>(s) << 16,
                       chunk[j] / static_cast<uint32_t>(image.width));
    pixel_list_.upload(entries.data(), sizeof(glm::uvec2) * n);
    ms += dispatch_list(bindings, n, k);
    samples.resize(pixel_vec4s(true) * n);
    pixels_.download(samples.data(), sizeof(vec4) * samples.size());
    for (size_t j = 0; j < chunk.size(); ++j) {
      // The strata's sums in the order a tile's dispatches add them (render/direct_pass.glsl).
      PixelPlanes sums = pixel_planes(samples, j * strata, n);
      for (size_t s = 1; s < strata; ++s) {
        const PixelPlanes stratum = pixel_planes(samples, j * strata + s, n);
        for (size_t plane = 0; plane < kPixelPlanes; ++plane) sums[plane] = sums[plane] + stratum[plane];
      }
      vec4 colour = sums[0];
      if (!counts_work_) colour = colour / static_cast<float>(strata);
      const uint32_t at = chunk[j];
      image.set(at, counts_work_ ? image.at(at) + glm::vec3(colour) : glm::vec3(colour));  // work: both passes'
      image.alpha[at] = colour.a;
      aovs[at] = aov_pixel(sums, std::round(colour.a * float(k * k)), k);
      aovs[at].error += edge[at] / static_cast<float>(k);  // the first pass's edge term over K (eq. 3)
    }
  }
  return ms;
}

void DirectPass::refine(std::span<const vk::Buffer* const> bindings, Image& image, std::vector<AovPixel>& aovs,
                        std::span<const float> edge, RenderStats& stats, std::size_t dispatched) {
  std::vector<PixelEstimate> estimates(aovs.size());
  double first_work = 0.0;
  for (size_t i = 0; i < aovs.size(); ++i) {
    estimates[i] = {aovs[i].error, edge[i], aovs[i].texture_term};
    first_work += refinement_cost(1, aovs[i].texture_term);
  }
  // The background's pixels were not dispatched (no texture term: one ray's cost each); a frame of background
  // alone has nothing to refine and its unit of work is priced by the first refinement.
  first_work -= static_cast<double>(aovs.size() - dispatched) * refinement_cost(1, false);
  first_work = std::max(first_work, refinement_cost(1, false));
  // Until measured, a unit of refinement work costs what it costs in the first pass.
  double ms_per_work = stats.gpu_ms / first_work, refine_ms = 0.0, work_done = 0.0;
  const std::optional<double> time_ms = adaptive_budget_.time_ms;
  const std::vector<RefinedPixel> plan =
      plan_refinement(estimates, adaptive_budget_, adaptive_samples_per_axis_,
                      time_ms ? (*time_ms - stats.gpu_ms) / ms_per_work : default_refinement_work(aovs.size()));
  // A time budget renders the plan in chunks of a tile's pixels, measuring the work's cost after each; the
  // other budgets in one (refine_group splits a level's pixels into dispatches as pixels_ holds them).
  const size_t chunk_limit = time_ms ? static_cast<size_t>(tile_size_) * tile_size_ : plan.size();
  size_t done = 0;
  while (done < plan.size()) {
    const std::span<const RefinedPixel> next(plan.begin() + done, std::min(plan.size() - done, chunk_limit));
    const size_t count =
        time_ms ? pixels_within_work(next, (*time_ms - stats.gpu_ms - refine_ms) / ms_per_work) : next.size();
    if (count == 0) break;
    for (int k : refinement_levels(adaptive_samples_per_axis_)) {
      // In frame order, so that neighbouring lanes trace neighbouring pixels.
      std::vector<uint32_t> group;
      for (const RefinedPixel& p : next.first(count))
        if (p.samples_per_axis == k) {
          group.push_back(p.index);
          work_done += refinement_cost(k, p.textured);
        }
      std::ranges::sort(group);
      refine_ms += refine_group(bindings, group, k, image, aovs, edge);
    }
    done += count;
    ms_per_work = refine_ms / work_done;
  }
  stats.gpu_ms += refine_ms;
  stats.refined_pixels = done;
}

std::vector<const vk::Buffer*> DirectPass::bindings() const {
  std::vector<const vk::Buffer*> slots = buffers_.bindings(pixels_);
  slots.resize(FACET_RENDER_BINDING_COUNT);
  slots[FACET_RENDER_BINDING_DIFFRACTION_COEFFICIENTS] = &diffraction_.coefficients;
  slots[FACET_RENDER_BINDING_DIFFRACTION_MATERIALS] = &diffraction_.materials;
  slots[FACET_RENDER_BINDING_DIFFRACTION_WAVELENGTHS] = &diffraction_.wavelengths;
  slots[FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS] = &diffraction_.preintegrated_words[0];
  slots[FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_1] = &diffraction_.preintegrated_words[1];
  slots[FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_2] = &diffraction_.preintegrated_words[2];
  slots[FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_3] = &diffraction_.preintegrated_words[3];
  slots[FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_SCALES] = &diffraction_.preintegrated_scales;
  slots[FACET_RENDER_BINDING_DIFFRACTION_OBSERVER] = &diffraction_.observer;
  slots[FACET_RENDER_BINDING_PIXEL_LIST] = &pixel_list_;
  slots[FACET_RENDER_BINDING_STATISTICS_QUEUE] = &statistics_queue_;
  return slots;
}

Image DirectPass::render(const Camera& camera, int width, int height, RenderStats* stats,
                         const TileProgress& progress) {
  if (width <= 0 || height <= 0) throw Error("image size must be positive");
  if (field_shadow_rays_ > 0)
    check_traversal(heightfield_camera_nodes(*scene_, camera.position), field_shadow_rays_, field_shadow_nodes_,
                    method_name_, false);
  buffers_.set_camera(*scene_, camera, width, height);
  const std::vector<const vk::Buffer*> bindings = this->bindings();
  Image image(width, height);
  image.alpha.resize(image.pixel_count());
  const int k = samples_per_axis_;
  const uint64_t planes = pixel_vec4s(writes_aovs_);
  std::vector<vec4> tile_pixels(planes * tile_size_ * tile_size_);  // rgba (a: coverage), then the AOV sums
  std::vector<AovPixel> aovs(writes_aovs_ ? image.pixel_count() : 0);
  RenderStats local;
  const int tiles = tile_count(width, height, tile_size_);
  // Each tile dispatches only the rectangle whose rays may meet the scene; the rest is background, written
  // here. Counting work keeps every pixel's own count (a miss's path too).
  const PixelCoverage coverage(bounds_, camera, width, height);
  const vec4 missed = missed_pixel(scene_->background, k);
  size_t dispatched = 0;
  for (int y0 = 0; y0 < height; y0 += tile_size_)
    for (int x0 = 0; x0 < width; x0 += tile_size_) {
      const PixelRect tile{x0, y0, std::min(x0 + tile_size_, width), std::min(y0 + tile_size_, height)};
      const PixelRect r = counts_work_ ? tile : coverage.covered(tile);
      const size_t n = r.empty() ? 0 : static_cast<size_t>(r.width()) * r.height();
      dispatched += n;
      if (n > 0) {
        for (int s = 0; s < k * k; ++s)  // ss:K: one stratum per dispatch, accumulated in pixels_
          local.gpu_ms += dispatch_tile(bindings, r.x0, r.y0, r.width(), r.height(), s);
        pixels_.download(tile_pixels.data(), sizeof(vec4) * planes * n);
      }
      for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
          const size_t at = image.index(x, y);
          const bool rendered = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
          const size_t i = rendered ? static_cast<size_t>(y - r.y0) * r.width() + (x - r.x0) : 0;
          const vec4 pixel = rendered ? tile_pixels[i] : missed;
          image.set(at, glm::vec3(pixel));
          image.alpha[at] = pixel.a;
          if (writes_aovs_)
            aovs[at] = aov_pixel(rendered ? pixel_planes(tile_pixels, i, n) : PixelPlanes{missed},
                                 std::round(pixel.a * float(k * k)), k);
        }
      ++local.tiles;
      if (progress) progress(local.tiles, tiles);
    }
  if (aovs_.error || adaptive_samples_per_axis_ > 0) {
    const std::vector<float> edge = edge_error(image, aovs, k);
    for (size_t i = 0; i < aovs.size(); ++i) aovs[i].error += edge[i];
    if (adaptive_samples_per_axis_ > 0) refine(bindings, image, aovs, edge, local, dispatched);
  }
  if (aovs_.any()) {
    const size_t first = add_aov_channels(image, aovs_);
    for (size_t i = 0; i < aovs.size(); ++i) set_aov_pixel(image, aovs_, first, i, aovs[i]);
  }
  if (stats) *stats = local;
  return image;
}

Image render_direct(vk::Context& context, const Scene& scene, int width, int height, const RenderMethod& method,
                    RenderStats* stats, const TileProgress& progress, int tile_size) {
  if (width <= 0 || height <= 0) throw Error("image size must be positive");
  DirectPass pass(context, scene, method, tile_size);
  return pass.render(scene.camera, width, height, stats, progress);
}

}  // namespace facet::gpu
