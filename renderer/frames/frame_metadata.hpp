// The EXR metadata of facet frames, written here only (README "Frames are scene-linear OpenEXR with
// metadata"; the keys are a contract).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "common/phase_timings.hpp"
#include "frames/frame_method.hpp"
#include "gpu/diffraction_upload.hpp"
#include "image/exr_io.hpp"
#include "scene/scene.hpp"

namespace facet::frames {

// facet:scene, facet:method, facet:spp, facet:device, facet:version, and facet:set (the scene's --set
// overrides as a JSON array of the PATH=VALUE texts) when it has any.
ExrMetadata frame_metadata(const Scene& scene, const std::string& method, std::int64_t samples_per_pixel,
                           const std::string& device);

// facet:render_ms and renderTimeSeconds (pbrt-v4's float), and facet:gpu_ms when the frame had
// device time (none for the CPU reference).
void add_timings(ExrMetadata& metadata, std::optional<double> gpu_ms, double wall_ms);

// The standard attributes other tools read, with pbrt-v4's names and types: samplesPerPixel (int),
// worldToCamera and worldToNDC (M44f, scene/camera_matrices.hpp) of a `width` x `height` frame of
// `camera`, and OpenEXR's chromaticities (the Rec. 709 primaries and D65 white of facet's linear RGB).
void add_standard_attributes(ExrMetadata& metadata, const Camera& camera, int width, int height,
                             std::int64_t samples_per_pixel);

// facet:phase:<name>_ms for every phase (load, upload, ..., render): where the wall clock went.
void add_phase_timings(ExrMetadata& metadata, const PhaseTimings& phases);

// facet:grid, facet:seed, facet:filter: the reference's sampling.
void add_reference_metadata(ExrMetadata& metadata, const ReferenceMethod& reference);

// facet:diffraction_method, facet:wavelengths, facet:taylor_terms, when the pass has diffraction materials.
void add_diffraction_metadata(ExrMetadata& metadata, const gpu::DiffractionBuffers& diffraction);

// facet:table_cache (hit, miss, off: where the `preintegrated` tables came from), with the timings: like
// them it changes between runs of the same frame.
void add_table_cache_metadata(ExrMetadata& metadata, const gpu::DiffractionBuffers& diffraction);

// facet:frame, for a frame of the scene's camera_path (nothing for -1, the still camera).
void add_frame_number(ExrMetadata& metadata, int frame);

}  // namespace facet::frames
