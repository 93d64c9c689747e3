// The reference image of a scene, rendered once and kept on disk under a content key, so reruns of
// `facet bench` skip the (slow) CPU reference unless something that changes it changed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace facet::report {

// Everything the reference image depends on.
struct ReferenceKey {
  std::filesystem::path scene_file;
  std::string renderer_version;
  int width = 0, height = 0;
  int grid = 0;
  std::uint64_t seed = 0;
  std::vector<std::string> overrides;  // --set of the scene
  int frame = -1;                      // a frame of the scene's camera path; -1: its still camera
};

// Hex digest of the scene file, its overrides, every file it references (named relative to the scene's
// folder, so a moved checkout still hits), the renderer version, the resolution, the grid, the seed and
// the camera path's frame.
std::string reference_cache_key(const ReferenceKey& key);

struct CachedReference {
  Image image;
  std::string key;
  bool cache_hit = false;
  double render_ms = 0.0;  // 0 on a hit
};

// Reads `cache_dir/<key>.exr` if it is there, readable, of the right size and tagged with the key;
// otherwise calls `render`, stores the result (float EXR, written atomically) and returns it.
CachedReference cached_reference(const std::filesystem::path& cache_dir, const ReferenceKey& key,
                                 const std::function<Image()>& render);

}  // namespace facet::report
