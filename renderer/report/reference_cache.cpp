#include "report/reference_cache.hpp"

#include <chrono>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/json_overrides.hpp"
#include "image/exr_io.hpp"

namespace facet::report {

namespace {

constexpr const char* kKeyAttribute = "facet:cache_key";

// The cached image, or an empty one when the file is missing, corrupt or not this key's.
Image read_cached(const std::filesystem::path& file, const std::string& key, int width, int height) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return {};
  try {
    ExrMetadata metadata;
    Image image = read_exr(file, &metadata);
    auto it = metadata.find(kKeyAttribute);
    const bool tagged = it != metadata.end() && std::holds_alternative<std::string>(it->second) &&
                        std::get<std::string>(it->second) == key;
    if (tagged && image.width == width && image.height == height) return image;
  } catch (const Error&) {
    // A torn or foreign file is recomputed, never trusted.
  }
  return {};
}

}  // namespace

std::string reference_cache_key(const ReferenceKey& key) {
  ContentHash hash;
  hash.add("facet reference cache v1\n");
  const std::filesystem::path base = key.scene_file.lexically_normal().parent_path();
  for (const auto& file : scene_dependencies(key.scene_file, key.overrides))
    hash.add_file(file, file.lexically_relative(base).generic_string());
  if (!key.overrides.empty()) hash.add("\nset " + overrides_text(key.overrides));  // none: the keys made before --set
  hash.add("\nversion " + key.renderer_version + "\nsize " + std::to_string(key.width) + "x" +
           std::to_string(key.height) + "\ngrid " + std::to_string(key.grid) + "\nseed " + std::to_string(key.seed));
  if (key.frame >= 0) hash.add("\nframe " + std::to_string(key.frame));  // none: the keys of still cameras
  return hash.hex();
}

CachedReference cached_reference(const std::filesystem::path& cache_dir, const ReferenceKey& key,
                                 const std::function<Image()>& render) {
  CachedReference result;
  result.key = reference_cache_key(key);
  const std::filesystem::path file = cache_dir / (result.key + ".exr");
  result.image = read_cached(file, result.key, key.width, key.height);
  if (result.image.width > 0) {
    result.cache_hit = true;
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  result.image = render();
  result.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::error_code error;
  std::filesystem::create_directories(cache_dir, error);
  if (error) throw Error(cache_dir.string() + ": cannot create the cache directory: " + error.message());
  write_exr(file, result.image, {{kKeyAttribute, result.key}, {"facet:version", key.renderer_version}},
            ExrPixelType::Float);
  return result;
}

}  // namespace facet::report
