// The sRGB transfer functions (IEC 61966-2-1) and the 8-bit display encoding built on them.
#pragma once

#include <cmath>
#include <cstdint>

namespace facet {

// Linear [0,1] -> sRGB-encoded [0,1] (the OETF; linear segment below 0.0031308).
inline double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// sRGB-encoded [0,1] -> linear [0,1] (the exact inverse of srgb_encode).
inline double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Display value in [0,1]: clamps to the displayable range first; NaN shows as black so a broken pixel
// is visible rather than a crash.
inline double srgb_display(double linear) {
  if (!(linear > 0.0)) return 0.0;
  return srgb_encode(linear < 1.0 ? linear : 1.0);
}

inline std::uint8_t srgb_display8(double linear) {
  return static_cast<std::uint8_t>(std::lround(255.0 * srgb_display(linear)));
}

}  // namespace facet
