// The facet::Error thrown by image readers and writers: one line, naming the file.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>

#include "common/error.hpp"

namespace facet {

// Library messages (OpenEXR, libpng) may span lines; the CLI prints exactly one.
inline Error io_error(const std::filesystem::path& path, std::string reason) {
  std::replace(reason.begin(), reason.end(), '\n', ' ');
  return Error(path.string() + ": " + reason);
}

}  // namespace facet
