// Test-only builder of small glTF 2.0 files (.gltf with a base64 buffer, or .glb), so each
// loader test states its input in code instead of depending on an opaque binary.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace facet::test {

class GltfTestWriter {
 public:
  GltfTestWriter() {
    doc_["asset"] = {{"version", "2.0"}};
    doc_["accessors"] = nlohmann::json::array();
    doc_["bufferViews"] = nlohmann::json::array();
  }

  // Appends `values` (any trivially copyable element type) as one buffer view and one accessor.
  template <typename T>
  int add_accessor(const std::vector<T>& values, int component_type, const std::string& type, size_t count,
                   bool normalized = false) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    const size_t offset = bin_.size();
    bin_.resize(offset + values.size() * sizeof(T));
    std::memcpy(bin_.data() + offset, values.data(), values.size() * sizeof(T));
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    nlohmann::json accessor = {{"bufferView", doc_["bufferViews"].size() - 1},
                               {"componentType", component_type},
                               {"count", count},
                               {"type", type}};
    if (normalized) accessor["normalized"] = true;
    doc_["accessors"].push_back(accessor);
    return static_cast<int>(doc_["accessors"].size() - 1);
  }

  nlohmann::json& doc() { return doc_; }

  void write_gltf(const std::filesystem::path& file) { std::ofstream(file) << gltf_text(); }

  // The buffer as a separate file `bin_name` beside `file`, referenced by a relative uri.
  void write_gltf_external(const std::filesystem::path& file, const std::string& bin_name) {
    finish_buffer(bin_name);
    std::ofstream(file) << doc_.dump();
    std::ofstream(file.parent_path() / bin_name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bin_.data()), static_cast<std::streamsize>(bin_.size()));
  }

  std::string gltf_text() {
    finish_buffer("data:application/octet-stream;base64," + base64(bin_));
    return doc_.dump();
  }

  // `json_text` replaces the document's JSON (for inputs nlohmann could not even hold).
  void write_glb(const std::filesystem::path& file, std::string json_text = "") {
    finish_buffer("");
    std::string json = json_text.empty() ? doc_.dump() : json_text;
    while (json.size() % 4 != 0) json.push_back(' ');
    std::vector<unsigned char> bin = bin_;
    while (bin.size() % 4 != 0) bin.push_back(0);
    std::ofstream out(file, std::ios::binary);
    const auto u32 = [&](uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
    u32(0x46546C67);  // "glTF"
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(json.size()));
    u32(0x4E4F534A);  // "JSON"
    out.write(json.data(), static_cast<std::streamsize>(json.size()));
    u32(static_cast<uint32_t>(bin.size()));
    u32(0x004E4942);  // "BIN\0"
    out.write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
  }

 private:
  void finish_buffer(const std::string& uri) {
    nlohmann::json buffer = {{"byteLength", bin_.size()}};
    if (!uri.empty()) buffer["uri"] = uri;
    doc_["buffers"] = nlohmann::json::array({buffer});
  }

  static std::string base64(const std::vector<unsigned char>& data) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
      const uint32_t b0 = data[i], b1 = i + 1 < data.size() ? data[i + 1] : 0,
                     b2 = i + 2 < data.size() ? data[i + 2] : 0;
      const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
      out += alphabet[(triple >> 18) & 63];
      out += alphabet[(triple >> 12) & 63];
      out += i + 1 < data.size() ? alphabet[(triple >> 6) & 63] : '=';
      out += i + 2 < data.size() ? alphabet[triple & 63] : '=';
    }
    return out;
  }

  nlohmann::json doc_;
  std::vector<unsigned char> bin_;
};

// A fresh, empty directory for one test's files, under the build tree.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(FACET_BINARY_DIR) / "test_scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace facet::test
