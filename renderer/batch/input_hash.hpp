// What decides whether an output is still up to date: the hash of its inputs, and of its bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "batch/items.hpp"
#include "batch/job.hpp"

namespace facet::batch {

// The scene file, its --set `overrides` and every file it references (scene_dependencies), each named
// relative to the scene's directory, so moving the whole tree keeps the hash. Throws facet::Error if
// unreadable.
std::string scene_files_hash(const std::filesystem::path& scene, const std::vector<std::string>& overrides = {});

// scene_files_hash + method + resolution + frame + the output settings + the renderer version; for
// the "reference" method also its grid and seed.
std::string item_inputs_hash(const std::string& scene_files, const Job& job, const Item& item,
                             const std::string& renderer_version);

// The hash of a file's bytes; empty if it cannot be read (a missing output is never up to date).
std::string file_hash(const std::filesystem::path& file);

}  // namespace facet::batch
