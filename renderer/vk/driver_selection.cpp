#include "vk/driver_selection.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace facet::vk {

namespace {

// The loader's list of driver manifests to use instead of its search. (VK_LOADER_DRIVERS_SELECT would
// filter the search, but the loader reports each driver it leaves out as a warning, which facet counts
// as a validation message.)
constexpr const char* kDriverFiles = "VK_DRIVER_FILES";
constexpr std::string_view kLavapipeManifest = "lvp_icd";  // lvp_icd.x86_64.json and the like
std::atomic<bool> selected = false;

std::string environment_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

// The folders the loader reads driver manifests from on Linux: $XDG_CONFIG_DIRS, /etc, $XDG_DATA_HOME
// and $XDG_DATA_DIRS, each with vulkan/icd.d.
std::vector<std::filesystem::path> manifest_folders() {
  std::vector<std::filesystem::path> folders;
  const auto add_list = [&](const std::string& list) {
    for (size_t begin = 0; begin <= list.size();) {
      const size_t end = std::min(list.find(':', begin), list.size());
      if (end > begin) folders.push_back(std::filesystem::path(list.substr(begin, end - begin)) / "vulkan/icd.d");
      begin = end + 1;
    }
  };
  add_list(environment_or("XDG_CONFIG_DIRS", "/etc/xdg"));
  folders.emplace_back("/etc/vulkan/icd.d");
  const std::string home = environment_or("HOME", "");
  add_list(environment_or("XDG_DATA_HOME", home.empty() ? "" : home + "/.local/share"));
  add_list(environment_or("XDG_DATA_DIRS", "/usr/local/share:/usr/share"));
  return folders;
}

// lavapipe's manifests where the loader would find them, in its order, joined by ':' (one per
// architecture may be installed; the loader skips those whose library this process cannot load).
std::string lavapipe_manifests() {
  std::string list;
  for (const std::filesystem::path& folder : manifest_folders()) {
    std::error_code error;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
      if (it->path().filename().string().find(kLavapipeManifest) != std::string::npos) {
        if (!list.empty()) list += ':';
        list += it->path().string();
      }
  }
  return list;
}

}  // namespace

void select_lavapipe_driver_only() {
  for (const char* steered : {kDriverFiles, "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES", "VK_LOADER_DRIVERS_SELECT",
                              "VK_LOADER_DRIVERS_DISABLE"})
    if (std::getenv(steered)) return;
  const std::string manifests = lavapipe_manifests();
  if (!manifests.empty()) selected = ::setenv(kDriverFiles, manifests.c_str(), 0) == 0;
}

bool lavapipe_driver_selected() { return selected; }

void select_every_driver() {
  if (selected.exchange(false)) ::unsetenv(kDriverFiles);
}

}  // namespace facet::vk
