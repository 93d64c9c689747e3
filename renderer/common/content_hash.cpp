#include "common/content_hash.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

#include <boost/uuid/detail/md5.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/json_overrides.hpp"

namespace facet {

struct ContentHash::State {
  boost::uuids::detail::md5 md5;
};

ContentHash::ContentHash() : state_(new State) {}
ContentHash::~ContentHash() { delete state_; }

void ContentHash::add(std::string_view bytes) { state_->md5.process_bytes(bytes.data(), bytes.size()); }

namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot read");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool is_json_file(const std::filesystem::path& path) {
  return path.extension() == ".json" || path.extension() == ".gltf";
}

// Strings of `value` naming existing regular files relative to `base`.
void collect_file_strings(const nlohmann::json& value, const std::filesystem::path& base,
                          std::set<std::filesystem::path>& found) {
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    if (text.empty() || text.size() > 4096 || text.rfind("data:", 0) == 0) return;
    std::error_code error;
    const std::filesystem::path candidate = (base / text).lexically_normal();
    if (std::filesystem::is_regular_file(candidate, error)) found.insert(candidate);
  } else if (value.is_structured()) {
    for (const auto& item : value) collect_file_strings(item, base, found);
  }
}

}  // namespace

void ContentHash::add_file(const std::filesystem::path& path, const std::string& name) {
  const std::string bytes = read_bytes(path);
  add(name);
  const std::string size = std::to_string(bytes.size());
  add("\n");  // name and size delimit the bytes
  add(size);
  add("\n");
  add(bytes);
}

std::string ContentHash::hex() {
  boost::uuids::detail::md5::digest_type digest;
  state_->md5.get_digest(digest);
  std::string text;
  for (unsigned word : digest) {
    char buffer[9];
    std::snprintf(buffer, sizeof buffer, "%08x", word);
    text += buffer;
  }
  return text;
}

std::vector<std::filesystem::path> scene_dependencies(const std::filesystem::path& scene_file,
                                                      const std::vector<std::string>& overrides) {
  std::set<std::filesystem::path> found{scene_file.lexically_normal()};
  std::vector<std::filesystem::path> pending{scene_file.lexically_normal()};
  std::set<std::filesystem::path> parsed;
  while (!pending.empty()) {
    const std::filesystem::path file = pending.back();
    pending.pop_back();
    if (!parsed.insert(file).second || !is_json_file(file)) continue;
    nlohmann::json document = nlohmann::json::parse(read_bytes(file), nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded()) continue;  // not JSON after all: hashed as bytes only
    if (file == scene_file.lexically_normal())
      for (const std::string& assignment : overrides) apply_override(document, assignment, file.string());
    std::set<std::filesystem::path> referenced;
    collect_file_strings(document, file.parent_path(), referenced);
    for (const auto& path : referenced)
      if (found.insert(path).second) pending.push_back(path);
  }
  return {found.begin(), found.end()};
}

}  // namespace facet
