// How finely an image file stores its colour samples, and how far a value read back may lie from the one
// written: a difference two files cannot resolve is no error (`facet compare` judges an error estimate's
// ranking at that resolution; docs/error_estimate.md, "How well it ranks the true error").
#pragma once

#include <filesystem>

namespace facet {

struct StoredPrecision {
  int fraction_bits = 23;   // a binary floating-point sample: float 23, half 10
  int min_exponent = -126;  // its smallest normal exponent: float -126, half -14
  int srgb_bits = 0;        // > 0: an sRGB-encoded integer sample of this many bits (PNG) instead
};

inline constexpr StoredPrecision kFloatSamples{23, -126, 0};
inline constexpr StoredPrecision kHalfSamples{10, -14, 0};
inline constexpr StoredPrecision srgb_samples(int bits) { return {0, 0, bits}; }

// The most a sample read back as `stored` may differ from the value written, rounded to nearest: half the
// spacing of the representable numbers at it (the wider one at a power of two), or for sRGB integers the
// wider of the half-steps on either side of its code, decoded to linear (values beyond [0, 1] as 0 or 1).
double rounding_bound(double stored, const StoredPrecision& precision);

// The precision of an image file as read_image reads it: an EXR's R (or Y) channel type, a PNG's bit
// depth. Throws facet::Error as read_image does.
StoredPrecision stored_precision(const std::filesystem::path& path);

}  // namespace facet
