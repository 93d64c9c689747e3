// Sizes in one-line error messages: bytes as MiB with one decimal ("285.0 MiB").
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace facet {

inline std::string format_mib(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f MiB", static_cast<double>(bytes) / 1048576.0);
  return text;
}

}  // namespace facet
