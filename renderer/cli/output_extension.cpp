#include "cli/output_extension.hpp"

#include <filesystem>

namespace facet::cli {

CLI::Validator output_extension(const std::string& extension, const std::string& what) {
  return CLI::Validator(
      [extension, what](std::string& path) -> std::string {
        if (std::filesystem::path(path).extension() == extension) return {};
        return path + " would hold " + what + " data: the name must end in " + extension;
      },
      "*" + extension);
}

}  // namespace facet::cli
