// Reading the materials with sub-pixel detail (scenes/README.md): "colormap_texture" and
// "microsurface", and the colour maps they use.
#pragma once

#include <filesystem>

#include "common/json_object_reader.hpp"
#include "scene/scene.hpp"

namespace facet {

// A colour map given as a built-in name ("viridis") or an object (scenes/README.md, "Colour maps").
Colormap read_colormap(const nlohmann::json& value, const std::string& file, const std::string& path);

// The rest of a material object whose "type" was already read; finishes the reader.
ColormapTextureMaterial read_colormap_texture_material(JsonObjectReader& r, const std::filesystem::path& base_dir);
MicrosurfaceMaterial read_microsurface_material(JsonObjectReader& r, const std::filesystem::path& base_dir);

}  // namespace facet
