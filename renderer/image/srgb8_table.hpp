// srgb_display8 by table: the 255 linear values at which the 8-bit sRGB code steps up, found once by
// bisection on srgb_display8 itself, so a look-up returns exactly what the formula does without a pow.
#pragma once

#include <array>
#include <cstdint>

namespace facet {

class Srgb8Table {
 public:
  Srgb8Table();
  // Equal to srgb_display8(linear) for every double (NaN and non-positive values give 0).
  std::uint8_t operator()(double linear) const {
    if (!(linear > 0.0)) return 0;
    // Branchless binary search for the last step at or below `linear` (steps_[0] = 0 stands for code 0).
    const double* base = steps_.data();
    for (std::size_t n = steps_.size(); n > 1; n -= n / 2) base = base[n / 2] <= linear ? base + n / 2 : base;
    return static_cast<std::uint8_t>(base - steps_.data());
  }

 private:
  std::array<double, 256> steps_{};  // steps_[k]: the smallest double whose code is k (k >= 1)
};

// The one table of the process, built on first use.
const Srgb8Table& srgb8_table();

}  // namespace facet
