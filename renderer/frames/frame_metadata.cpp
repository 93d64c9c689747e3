#include "frames/frame_metadata.hpp"

#include "common/json_overrides.hpp"
#include "scene/camera_matrices.hpp"
#include "scene/grating/diffraction_method.hpp"

namespace facet::frames {

namespace {

// pbrt-v4's layout: m[row][column] of the column-vector matrix (scene/camera_matrices.hpp); glm
// indexes [column][row].
ExrMatrix exr_matrix(const glm::dmat4& m) {
  ExrMatrix matrix;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) matrix[row][column] = static_cast<float>(m[column][row]);
  return matrix;
}

// ITU-R BT.709 primaries and the D65 white point (CIE 1931 xy).
constexpr ExrChromaticities kRec709{{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f}};

}  // namespace

ExrMetadata frame_metadata(const Scene& scene, const std::string& method, std::int64_t samples_per_pixel,
                           const std::string& device) {
  ExrMetadata metadata{{"facet:scene", scene.source.string()},
                       {"facet:method", method},
                       {"facet:spp", samples_per_pixel},
                       {"facet:device", device},
                       {"facet:version", std::string(FACET_VERSION)}};
  if (!scene.overrides.empty()) metadata["facet:set"] = overrides_text(scene.overrides);
  return metadata;
}

void add_timings(ExrMetadata& metadata, std::optional<double> gpu_ms, double wall_ms) {
  if (gpu_ms) metadata["facet:gpu_ms"] = *gpu_ms;
  metadata["facet:render_ms"] = wall_ms;
  metadata["renderTimeSeconds"] = static_cast<float>(wall_ms / 1000.0);
}

void add_standard_attributes(ExrMetadata& metadata, const Camera& camera, int width, int height,
                             std::int64_t samples_per_pixel) {
  metadata["samplesPerPixel"] = samples_per_pixel;
  metadata["worldToCamera"] = exr_matrix(world_to_camera(camera));
  metadata["worldToNDC"] = exr_matrix(world_to_ndc(camera, width, height));
  metadata["chromaticities"] = kRec709;
}

void add_phase_timings(ExrMetadata& metadata, const PhaseTimings& phases) {
  for (const Phase& phase : phases.phases()) metadata["facet:phase:" + phase.name + "_ms"] = phase.ms;
}

void add_reference_metadata(ExrMetadata& metadata, const ReferenceMethod& reference) {
  metadata["facet:grid"] = static_cast<std::int64_t>(reference.grid);
  metadata["facet:seed"] = reference.seed;
  metadata["facet:filter"] = std::string("box");
}

void add_diffraction_metadata(ExrMetadata& metadata, const gpu::DiffractionBuffers& diffraction) {
  if (diffraction.most_wavelengths == 0) return;  // no diffraction material
  metadata["facet:diffraction_method"] = std::string(diffraction::diffraction_method_name(diffraction.method));
  metadata["facet:wavelengths"] = std::int64_t{diffraction.most_wavelengths};
  metadata["facet:taylor_terms"] = std::int64_t{diffraction.most_taylor};
}

void add_table_cache_metadata(ExrMetadata& metadata, const gpu::DiffractionBuffers& diffraction) {
  if (diffraction.most_wavelengths > 0 && diffraction.method == diffraction::DiffractionMethod::Preintegrated)
    metadata["facet:table_cache"] = std::string(diffraction::table_cache_use_name(diffraction.table_cache));
}

void add_frame_number(ExrMetadata& metadata, int frame) {
  if (frame >= 0) metadata["facet:frame"] = static_cast<std::int64_t>(frame);
}

}  // namespace facet::frames
