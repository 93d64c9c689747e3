// Reproducible standard-normal white noise.
//
// std::mt19937_64 is fully specified by the C++ standard; std::normal_distribution is not (its
// algorithm is implementation-defined), so the normal deviates are made here: 53-bit uniforms in
// (0, 1) from the top bits of each 64-bit word, then Box–Muller (both outputs used). The same seed
// gives the same bytes with any standard library whose log/cos/sin round identically (same libm).
#pragma once

#include <cstdint>
#include <random>

namespace facet::assets {

class GaussianWhiteNoise {
 public:
  explicit GaussianWhiteNoise(std::uint64_t seed) : engine_(seed) {}
  double next();

 private:
  double uniform_open();  // in (0, 1): never 0, so log() is finite
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace facet::assets
