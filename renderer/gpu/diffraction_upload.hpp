// The diffraction materials of a scene in the direct pass's texel buffers (the slots
// FACET_RENDER_BINDING_DIFFRACTION_* of shaders/layout/render_layout.glsl): every material's spectral
// tables (float) and wavelength samples, prepared for this render (diffraction/prepared_diffraction.hpp).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/order_wavelengths.hpp"
#include "diffraction/preintegrated_cache.hpp"
#include "diffraction/prepared_diffraction.hpp"
#include "gpu/diffraction_fast_upload.hpp"
#include "gpu/diffraction_layout.hpp"
#include "gpu/preintegrated_slices.hpp"
#include "scene/scene.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

struct DiffractionBuffers {
  vk::Buffer coefficients;          // vec2: the tables of all materials, one after another
  vk::Buffer materials;             // GpuDiffractionMaterial, in the order of the scene's diffraction materials
  vk::Buffer wavelengths;           // vec4 (lambda nm, XYZ weight)
  // uint: `preintegrated` tables (gpu/diffraction_fast_upload.hpp), one buffer per word binding
  // (FACET_RENDER_PREINTEGRATED_SLICES; a one-word placeholder where a slice is unused)
  std::vector<vk::Buffer> preintegrated_words;
  PreintegratedSlices preintegrated_slices;  // how the words are split over them
  vk::Buffer preintegrated_scales;  // float: their per-term scales
  vk::Buffer observer;              // vec4: the `orders` observer tables, XYZ per nm
  diffraction::DiffractionMethod method = diffraction::DiffractionMethod::Spectral;  // kDiffractionMethod
  int most_wavelengths = 0;  // the most wavelength samples / Taylor terms of any material (metadata)
  int most_taylor = 0;
  // `preintegrated`: Hit when every material's tables came from the cache, Miss when any was built.
  diffraction::TableCacheUse table_cache = diffraction::TableCacheUse::Off;
};

// Lavapipe stops every loop of a shader invocation, silently, once all its loops together have run
// 65535 iterations (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS). The spectral loop of one ray runs
// K (1 + B (1 + ceil((N - 1) / 8))) of them (render/diffraction_taylor.glsl: K wavelengths, B bins,
// N Taylor terms); kTraceLoopReserve per ray is left for tracing (BVH, planes, spheres, shadow ray).
constexpr int kLoopIterationLimit = 65535;
constexpr int kTraceLoopReserve = 4096;
long diffraction_loop_iterations(const diffraction::PreparedDiffraction& prepared);

// The same bound for the `orders` walk (render/diffraction_orders.glsl) of a restricted plan: the
// candidates' first pass, then per node (at most F.13's, over F.10's candidates) the
// walk and its advance, the share's loops over the orders within reach, and the lattice bins'
// Taylor sums (docs/diffraction_fast_paths.md, "Loop limit"); over_pixel (`filtered`, eq. O3): F.10's
// candidates with a pixel's reach (two passes), then at most pixel_budget + candidates nodes of one bin's Taylor sum.
long order_loop_iterations(const diffraction::OrderWavelengths& plan, const diffraction::SpectralTables& tables,
                           bool over_pixel);

// What the pass needs of the scene's diffraction before any table is read or built: the method and the
// preintegrated words' layout (the pipeline's specialization), and the host data the upload places. The
// pass specialises its pipeline from the plan and uploads the same plan, so the compiled layout and the
// bound words cannot disagree; planning is cheap (spectral tables, headers, checks), reading the tables
// is not, and the pass compiles while it reads. Move-only: `fast` points into `prepared`.
struct DiffractionPlan {
  DiffractionPlan() = default;
  DiffractionPlan(DiffractionPlan&&) = default;
  DiffractionPlan& operator=(DiffractionPlan&&) = default;
  DiffractionPlan(const DiffractionPlan&) = delete;
  DiffractionPlan& operator=(const DiffractionPlan&) = delete;

  diffraction::DiffractionMethod method = diffraction::DiffractionMethod::Spectral;  // kDiffractionMethod
  PreintegratedSlices preintegrated_slices;  // kPreintegratedSlices, kPreintegratedSliceWords
  std::vector<std::optional<diffraction::PreparedDiffraction>> prepared;  // per scene material
  std::vector<glm::vec2> coefficients;
  std::vector<GpuDiffractionMaterial> materials;
  std::vector<glm::vec4> wavelengths;
  FastPathData fast;  // the preintegrated tables' places (their words not yet read), the orders' data
  int most_wavelengths = 0;
  int most_taylor = 0;
};

// Diffraction material i of the scene (counting only diffraction materials, in scene order) is
// entry i of `materials`: the index scene_upload puts in GpuMaterial::kind.y. Throws facet::Error
// if the tables exceed what the device's texel bindings or memory hold, or if one ray of a material would exceed
// the loop limit above (spectral and orders; ss:K runs one ray per invocation and dispatch), or if the materials ask
// for different methods (gpu/diffraction_fast_upload.hpp): all before any preintegrated table is read or built.
DiffractionPlan plan_diffraction(const vk::Context& context, const Scene& scene,
                                 const diffraction::DiffractionSettings& settings = {});

// Whether the pass may run the spectral path under `orders`: some material's orders are not restricted
// (not periodic, or unresolved: F.10, F.11 of docs/diffraction_fast_paths.md; GpuDiffractionMaterial's
// fast_scalars.z is 0). False under the other methods and without diffraction.
bool orders_fall_back(const DiffractionPlan& plan);

// The plan's buffers: the preintegrated tables read from the table cache or built (the slow part), then
// everything uploaded. A scene without diffraction gets one-element placeholders (the pass binds them, its
// shader never reads them).
DiffractionBuffers upload_diffraction(vk::Context& context, DiffractionPlan plan);

// upload_diffraction(context, plan_diffraction(context, scene, settings)).
DiffractionBuffers upload_diffraction(vk::Context& context, const Scene& scene,
                                      const diffraction::DiffractionSettings& settings = {});

}  // namespace facet::gpu
