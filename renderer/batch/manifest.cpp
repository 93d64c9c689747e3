#include "batch/manifest.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "image/atomic_file.hpp"

namespace facet::batch {

namespace {

using Json = nlohmann::json;
constexpr int kManifestVersion = 1;

Json to_json(const ManifestEntry& entry) {
  Json json = {{"scene", entry.scene}, {"method", entry.method},
               {"frame", entry.frame}, {"inputs_hash", entry.inputs_hash},
               {"files", entry.files}, {"render_ms", entry.render_ms}};
  if (!entry.overrides.empty()) json["set"] = entry.overrides;
  return json;
}

ManifestEntry from_json(const Json& json) {
  ManifestEntry entry;
  entry.scene = json.at("scene").get<std::string>();
  if (json.contains("set")) entry.overrides = json.at("set").get<std::vector<std::string>>();
  entry.method = json.at("method").get<std::string>();
  // get<int>() of a double out of int range is undefined behaviour: only integers in range pass.
  const Json& frame = json.at("frame");
  if (!frame.is_number_integer() || frame < 0 || frame > std::numeric_limits<int>::max())
    throw Json::other_error::create(501, "frame must be a non-negative integer", &frame);
  entry.frame = frame.get<int>();
  entry.inputs_hash = json.at("inputs_hash").get<std::string>();
  entry.files = json.at("files").get<std::map<std::string, std::string>>();
  entry.render_ms = json.at("render_ms").get<double>();
  return entry;
}

}  // namespace

Manifest read_manifest(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return {};
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string problem = path.string() + ": not a readable facet manifest (delete it to render everything again)";
  if (!in.good() && !in.eof()) throw Error(problem);
  const Json document = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded() || !document.is_object() || document.value("facet_manifest", Json()) != kManifestVersion)
    throw Error(problem);
  Manifest manifest;
  try {
    for (const auto& [output, entry] : document.at("items").items()) manifest[output] = from_json(entry);
  } catch (const Json::exception&) {
    throw Error(problem);
  }
  return manifest;
}

void write_manifest(const std::filesystem::path& path, const Manifest& manifest) {
  Json items = Json::object();
  for (const auto& [output, entry] : manifest) items[output] = to_json(entry);
  const std::string text = Json{{"facet_manifest", kManifestVersion}, {"items", items}}.dump(1) + "\n";
  write_file_atomically(path, text);
}

std::filesystem::path shard_manifest_path(const std::filesystem::path& manifest, const Shard& shard) {
  return manifest.parent_path() / (manifest.stem().string() + ".shard-" + std::to_string(shard.index) + "-of-" +
                                   std::to_string(shard.count) + ".json");
}

std::vector<std::filesystem::path> find_shard_manifests(const std::filesystem::path& manifest) {
  const std::filesystem::path directory = manifest.parent_path().empty() ? "." : manifest.parent_path();
  const std::string prefix = manifest.stem().string() + ".shard-";
  const std::regex shard_suffix(R"(\d+-of-\d+\.json)");
  std::vector<std::filesystem::path> found;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && std::regex_match(name.substr(prefix.size()), shard_suffix))
      found.push_back(manifest.parent_path() / name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

void merge_manifest(Manifest& into, const Manifest& from) {
  for (const auto& [output, entry] : from) into[output] = entry;
}

}  // namespace facet::batch
