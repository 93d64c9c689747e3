#include "assets/white_noise.hpp"

#include <cmath>
#include <numbers>

namespace facet::assets {

double GaussianWhiteNoise::uniform_open() {
  // (k + 1/2) / 2^53 for k in [0, 2^53): the centres of 2^53 equal bins of (0, 1).
  return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53;
}

double GaussianWhiteNoise::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double r = std::sqrt(-2.0 * std::log(uniform_open()));
  double phi = 2.0 * std::numbers::pi * uniform_open();
  spare_ = r * std::sin(phi);
  has_spare_ = true;
  return r * std::cos(phi);
}

}  // namespace facet::assets
