// Scalar textures and height maps named in a scene file (scenes/README.md, "Texture sources"):
//   {"file": "tex.exr", "channel": "Y"}  an EXR channel, or an 8/16-bit grey PNG (values / (2^bits − 1)),
//                                         relative to the scene file's directory;
//   {"noise": {fBm parameters}}           assets::generate_fbm_noise, generated at load;
//   {"gaussian": {generator parameters}}  assets::generate_gaussian_heightfield (height fields only).
// Generation is deterministic in the parameters (seed included); NaN or inf texels are an error.
#pragma once

#include <filesystem>
#include <optional>

#include "common/json_object_reader.hpp"
#include "scene/scene.hpp"

namespace facet {

// `texel_size`: the world texel size Δ of a height field, which a "gaussian" source needs (its
// correlation lengths and σ_h are in world units); nullopt where "gaussian" is not allowed.
ScalarTexture read_scalar_source(JsonObjectReader r, const std::filesystem::path& base_dir,
                                 std::optional<double> texel_size);

}  // namespace facet
