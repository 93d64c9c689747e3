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
#include "scene/scene.hpp"

namespace facet::gpu {

// Bilinear-interpolation tolerance of the tables relative to the local envelope (eq. F.6): the
// setting measured in docs/diffraction_fast_paths.md (3.1e-3 of the peak on the fingers grating).
constexpr double kPreintegrationTolerance = 1e-2;

// The method every diffraction material of the scene is rendered with: settings.method, else the
// materials' own "method". Throws facet::Error when the materials ask for different ones (the
// pass compiles one method in; `--diffraction` picks one for all). Spectral without diffraction.
diffraction::DiffractionMethod scene_diffraction_method(const Scene& scene,
                                                        const diffraction::DiffractionSettings& settings);

struct FastPathData {
  std::vector<std::uint32_t> preintegrated_words;
  std::vector<float> preintegrated_scales;
  std::vector<glm::vec4> observer;  // XYZ per nm (xyz_density), w unused
  std::uint64_t cell_words = 0;     // the most words one cell of any preintegrated table spans
};

// Fills material's preintegrated_* / order_* / fast_* fields for `method` (the others stay zero)
// and appends its tables to `data`. The preintegrated tables are refused (facet::Error, one line
// with the sizes) when `data` would exceed max_bytes of device memory; a grating that is not periodic gets
// periodic = 0, and the pass then runs the spectral path for it under `orders`. The tables are read
// from and kept in `table_cache` (empty: none); the result says whether they came from it.
diffraction::TableCacheUse append_fast_paths(FastPathData& data, GpuDiffractionMaterial& material, const Scene& scene,
                                             std::uint32_t scene_material,
                                             const diffraction::PreparedDiffraction& prepared,
                                             diffraction::DiffractionMethod method, std::uint64_t max_bytes,
                                             const std::filesystem::path& table_cache);

}  // namespace facet::gpu
