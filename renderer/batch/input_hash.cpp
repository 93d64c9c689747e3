#include "batch/input_hash.hpp"

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/json_overrides.hpp"

namespace facet::batch {

std::string scene_files_hash(const std::filesystem::path& scene, const std::vector<std::string>& overrides) {
  ContentHash hash;
  const std::filesystem::path directory = scene.lexically_normal().parent_path();
  for (const auto& file : scene_dependencies(scene, overrides))
    hash.add_file(file, file.lexically_relative(directory).generic_string());
  if (!overrides.empty()) hash.add("\nset " + overrides_text(overrides));  // none: the hashes made before --set
  return hash.hex();
}

std::string item_inputs_hash(const std::string& scene_files, const Job& job, const Item& item,
                             const std::string& renderer_version) {
  ContentHash hash;
  // Fields separated by NUL, which none of them contains.
  const auto field = [&](const std::string& text) { hash.add(text + '\0'); };
  field(scene_files);
  field(item.method);
  field(std::to_string(job.width) + "x" + std::to_string(job.height));
  field(std::to_string(item.frame));
  field(job.pixel_type);
  field(job.preview ? "preview " + std::to_string(job.exposure) : "no preview");
  if (!job.aov.empty()) field("aov " + job.aov);  // absent: the hash of a job from before the key
  if (item.method == "reference") field("grid " + std::to_string(job.grid) + " seed " + std::to_string(job.seed));
  field(renderer_version);
  return hash.hex();
}

std::string file_hash(const std::filesystem::path& file) {
  try {
    ContentHash hash;
    hash.add_file(file, "");
    return hash.hex();
  } catch (const Error&) {
    return {};
  }
}

}  // namespace facet::batch
