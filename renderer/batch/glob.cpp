#include "batch/glob.hpp"

#include <fnmatch.h>

#include <algorithm>

#include "common/error.hpp"

namespace facet::batch {

namespace {

bool has_wildcard(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

}  // namespace

std::vector<std::filesystem::path> expand_glob(const std::string& pattern, const std::filesystem::path& base) {
  const std::filesystem::path relative(pattern);
  const std::filesystem::path full = relative.is_absolute() ? relative : base / relative;
  if (!has_wildcard(pattern)) return {full.lexically_normal()};

  // Expand one component at a time: every partial match is a directory we list the next level of.
  std::vector<std::filesystem::path> matches{full.root_path()};
  for (const std::filesystem::path& component : full.relative_path()) {
    const std::string part = component.string();
    std::vector<std::filesystem::path> next;
    for (const std::filesystem::path& prefix : matches) {
      if (!has_wildcard(part)) {
        next.push_back(prefix / component);
        continue;
      }
      std::error_code error;
      for (const auto& entry : std::filesystem::directory_iterator(prefix.empty() ? "." : prefix, error)) {
        const std::string name = entry.path().filename().string();
        if (::fnmatch(part.c_str(), name.c_str(), FNM_PERIOD) == 0) next.push_back(prefix / name);
      }
    }
    matches = std::move(next);
  }
  std::erase_if(matches, [](const std::filesystem::path& p) {
    std::error_code error;
    return !std::filesystem::exists(p, error);
  });
  if (matches.empty()) throw Error(pattern + ": matches no file");
  for (auto& path : matches) path = path.lexically_normal();
  std::sort(matches.begin(), matches.end());
  return matches;
}

}  // namespace facet::batch
