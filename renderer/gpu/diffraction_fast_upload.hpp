// The data of the fast diffraction paths (docs/diffraction_fast_paths.md, "Rendering") for the
// direct pass: `preintegrated` tables over the scene's view domain and the
// `orders` lattice with its observer table, appended per material next to the
// spectral data of gpu/diffraction_upload.cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/preintegrated_cache.hpp"
#include "diffraction/prepared_diffraction.hpp"
#include "gpu/diffraction_layout.hpp"
#include "gpu/preintegrated_slices.hpp"
#include "scene/scene.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

// Bilinear-interpolation tolerance of the tables relative to the local envelope (eq. F.6): the
// setting measured in docs/diffraction_fast_paths.md (3.1e-3 of the peak on the fingers grating).
constexpr double kPreintegrationTolerance = 1e-2;

// The method every diffraction material of the scene is rendered with: settings.method, else the
// materials' own "method". Throws facet::Error when the materials ask for different ones (the
// pass compiles one method in; `--diffraction` picks one for all). Spectral without diffraction.
diffraction::DiffractionMethod scene_diffraction_method(const Scene& scene,
                                                        const diffraction::DiffractionSettings& settings);

// One material's `preintegrated` tables, placed in the words (word_offset) and scales before they
// are read or built (upload_preintegrated_words).
struct PendingTables {
  std::string material;  // its name, for errors
  const diffraction::PreparedDiffraction* prepared = nullptr;
  diffraction::PreintegratedDomain domain;
  diffraction::PreintegrationSettings settings;
  diffraction::PreintegratedTables header;  // preintegrated_header's
  std::uint64_t word_offset = 0;
};

struct FastPathData {
  std::vector<PendingTables> preintegrated;
  std::uint64_t preintegrated_word_count = 0;  // of all materials' tables
  std::vector<float> preintegrated_scales;     // placed with the tables, filled by upload_preintegrated_words
  std::vector<glm::vec4> observer;             // XYZ per nm (xyz_density), w unused
  std::uint64_t cell_words = 0;                // the most words one cell of any preintegrated table spans
};

// Fills material's preintegrated_* / order_* / fast_* fields for `method` (the others stay zero)
// and appends its data to `data`: the `orders` tables, or the place of the preintegrated tables, which
// are refused (facet::Error, one line with the sizes) when `data` would exceed max_bytes of device memory.
// A grating that is not periodic gets periodic = 0, and the pass then runs the spectral path for it
// under `orders`. over_pixel: `orders` runs over the pixel (its loop bound is that walk's). `prepared`
// must outlive `data`.
void append_fast_paths(FastPathData& data, GpuDiffractionMaterial& material, const Scene& scene,
                       std::uint32_t scene_material, const diffraction::PreparedDiffraction& prepared,
                       diffraction::DiffractionMethod method, bool over_pixel, std::uint64_t max_bytes);

struct PreintegratedWords {
  std::vector<vk::Buffer> buffers;  // one per slice
  PreintegratedSlices slices;
  diffraction::TableCacheUse use = diffraction::TableCacheUse::Off;  // Hit: every table came from the cache
};

// The tables placed in `data`, from `table_cache` (empty: none) or built. A device that imports host
// memory (lavapipe) binds one material's cached tables where the file's mapping holds them, when one
// binding holds them; else they are read or built straight into the word bindings' memory when the
// device maps it and one binding holds them, else into one staging buffer copied to the bindings. Fills
// data.preintegrated_scales. One binding per range of `slices`
// (slice_preintegrated_words of data's words: the layout the pass's pipeline was specialised for).
PreintegratedWords upload_preintegrated_words(vk::Context& context, FastPathData& data,
                                              const PreintegratedSlices& slices,
                                              const std::filesystem::path& table_cache);

}  // namespace facet::gpu
