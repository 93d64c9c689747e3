#include "frames/frame_metadata.hpp"

#include "scene/grating/diffraction_method.hpp"

namespace facet::frames {

ExrMetadata frame_metadata(const Scene& scene, const std::string& method, std::int64_t samples_per_pixel,
                           const std::string& device) {
  return {{"facet:scene", scene.source.string()},
          {"facet:method", method},
          {"facet:spp", samples_per_pixel},
          {"facet:device", device},
          {"facet:version", std::string(FACET_VERSION)}};
}

void add_timings(ExrMetadata& metadata, std::optional<double> gpu_ms, double wall_ms) {
  if (gpu_ms) metadata["facet:gpu_ms"] = *gpu_ms;
  metadata["facet:render_ms"] = wall_ms;
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

void add_frame_number(ExrMetadata& metadata, int frame) {
  if (frame >= 0) metadata["facet:frame"] = static_cast<std::int64_t>(frame);
}

}  // namespace facet::frames
