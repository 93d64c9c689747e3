// Content hashes for the reference cache: a digest of bytes, and the files a scene depends on.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

// Accumulates bytes into a 128-bit MD5 digest (collisions are not a concern for a cache key:
// nobody forges scenes against it), returned as 32 lowercase hex digits.
class ContentHash {
 public:
  ContentHash();
  ~ContentHash();
  ContentHash(const ContentHash&) = delete;
  ContentHash& operator=(const ContentHash&) = delete;

  void add(std::string_view bytes);
  // `name`, then the file's byte count and bytes; throws facet::Error if it cannot be read.
  void add_file(const std::filesystem::path& path, const std::string& name);
  std::string hex();

 private:
  struct State;
  State* state_;
};

// The scene file and every file it references, transitively: each string in a JSON file (the scene,
// a glTF) that names an existing regular file relative to that file's directory, the scene read with
// its --set `overrides` (a value may name a file). Sorted, unique.
std::vector<std::filesystem::path> scene_dependencies(const std::filesystem::path& scene_file,
                                                      const std::vector<std::string>& overrides = {});

}  // namespace facet
