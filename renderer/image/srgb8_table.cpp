#include "image/srgb8_table.hpp"

#include <bit>

#include "image/srgb.hpp"

namespace facet {

namespace {

// The smallest positive double whose code is at least `code`, by bisection over the bit patterns of
// [0, 1] (ordered like the values they encode). srgb_display8 is non-decreasing: pow is monotone.
double first_with_code(int code) {
  std::uint64_t below = std::bit_cast<std::uint64_t>(0.0), at = std::bit_cast<std::uint64_t>(1.0);
  while (at - below > 1) {
    const std::uint64_t mid = below + (at - below) / 2;
    (srgb_display8(std::bit_cast<double>(mid)) >= code ? at : below) = mid;
  }
  return std::bit_cast<double>(at);
}

}  // namespace

Srgb8Table::Srgb8Table() {
  for (int code = 1; code < static_cast<int>(steps_.size()); ++code) steps_[code] = first_with_code(code);
}

const Srgb8Table& srgb8_table() {
  static const Srgb8Table table;
  return table;
}

}  // namespace facet
