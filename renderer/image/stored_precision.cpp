#include "image/stored_precision.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "image/srgb.hpp"

namespace facet {

namespace {

// Half the spacing of binary floating-point numbers with `fraction_bits` at |stored|: 2^(e - bits - 1)
// for its exponent e = floor(log2 |stored|), no lower than the smallest normal exponent (the subnormals
// share its spacing). At a power of two that is the spacing above it, the wider one.
double floating_point_bound(double stored, int fraction_bits, int min_exponent) {
  int exponent = min_exponent;
  if (stored != 0.0) {
    int k = 0;
    std::frexp(stored, &k);  // |stored| = m 2^k, m in [0.5, 1)
    exponent = std::max(k - 1, min_exponent);
  }
  return std::ldexp(1.0, exponent - fraction_bits - 1);
}

// The wider half-step around the code of `stored` among sRGB integers of `bits` bits, in linear units.
double srgb_integer_bound(double stored, int bits) {
  const double codes = std::ldexp(1.0, bits) - 1.0;
  const double code = std::round(srgb_encode(std::clamp(stored, 0.0, 1.0)) * codes);
  const double at = srgb_decode(code / codes);
  const double above = srgb_decode(std::min(code + 0.5, codes) / codes) - at;
  const double below = at - srgb_decode(std::max(code - 0.5, 0.0) / codes);
  return std::max(above, below);
}

}  // namespace

double rounding_bound(double stored, const StoredPrecision& precision) {
  if (precision.srgb_bits > 0) return srgb_integer_bound(stored, precision.srgb_bits);
  return floating_point_bound(stored, precision.fraction_bits, precision.min_exponent);
}

StoredPrecision stored_precision(const std::filesystem::path& path) {
  const auto extension = path.extension();
  if (extension == ".exr") return exr_colour_type(path) == ExrPixelType::Half ? kHalfSamples : kFloatSamples;
  if (extension == ".png") return srgb_samples(read_png(path).bit_depth);
  throw Error(path.string() + ": not an image facet reads (.exr or .png)");
}

}  // namespace facet
