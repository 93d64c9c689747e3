// Numbers in one-line error messages: shortest round-trip form ("0.25", "1e-09", "nan").
#pragma once

#include <charconv>
#include <string>

namespace facet::assets {

inline std::string format_number(double value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace facet::assets
