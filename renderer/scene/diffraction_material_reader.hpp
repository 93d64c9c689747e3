// Reading a "diffraction" material (scenes/README.md): a grating, inline or from a file, with its
// tolerance, light spectrum, sample-count overrides and diffuse base.
#pragma once

#include <filesystem>

#include "common/json_object_reader.hpp"
#include "scene/scene.hpp"

namespace facet {

// The rest of a material object whose "type" was already read; finishes the reader. Grating
// files are relative to `base_dir` (the scene file's folder).
DiffractionMaterial read_diffraction_material(JsonObjectReader& r, const std::filesystem::path& base_dir);

}  // namespace facet
