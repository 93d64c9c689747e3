#include "assets/fbm_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "assets/format_number.hpp"
#include "common/error.hpp"

namespace facet::assets {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Frequency of octave k, f_k = round(f_0 λ^k) (at least 1).
long long octave_frequency(const FbmParams& p, int k) {
  return std::max(1LL, std::llround(p.base_frequency * std::pow(p.lacunarity, k)));
}

struct Gradient {
  double x, y;
};

// The unit gradient at lattice point (i, j) of octave k: its angle is a hash of (seed, k, i mod f, j mod f).
Gradient lattice_gradient(const FbmParams& p, int k, long long frequency, long long i, long long j) {
  auto wrap = [frequency](long long v) {
    return static_cast<std::uint64_t>(((v % frequency) + frequency) % frequency);
  };
  std::uint64_t h = splitmix64(splitmix64(splitmix64(p.seed ^ splitmix64(static_cast<std::uint64_t>(k))) ^ wrap(i)) ^
                               (wrap(j) << 32));
  double angle = 2.0 * std::numbers::pi * static_cast<double>(h >> 11) * 0x1.0p-53;
  return {std::cos(angle), std::sin(angle)};
}

// Gradient noise of `frequency` cells per tile at (x, y); `gradient_at(i, j)` gives the lattice gradients.
template <class GradientAt>
double gradient_noise(long long frequency, double x, double y, const GradientAt& gradient_at) {
  double fx = x * static_cast<double>(frequency), fy = y * static_cast<double>(frequency);
  long long i = static_cast<long long>(std::floor(fx)), j = static_cast<long long>(std::floor(fy));
  double dx = fx - static_cast<double>(i), dy = fy - static_cast<double>(j);
  auto corner = [&](long long ci, long long cj, double ox, double oy) {
    Gradient g = gradient_at(ci, cj);
    return g.x * ox + g.y * oy;
  };
  double n00 = corner(i, j, dx, dy);
  double n10 = corner(i + 1, j, dx - 1.0, dy);
  double n01 = corner(i, j + 1, dx, dy - 1.0);
  double n11 = corner(i + 1, j + 1, dx - 1.0, dy - 1.0);
  double u = fade(dx), v = fade(dy);
  return (1.0 - v) * ((1.0 - u) * n00 + u * n10) + v * ((1.0 - u) * n01 + u * n11);
}

// One octave's gradients for a whole texture. Where the lattice has no more points than 4x the
// texels, each is hashed once and shared by the (up to four) texels around it (a sin and a cos per
// point instead of per texel corner: the generator's cost); finer octaves hash per corner.
class OctaveGradients {
 public:
  OctaveGradients(const FbmParams& p, int k, long long frequency, long long texels)
      : p_(p), k_(k), frequency_(frequency) {
    if (frequency * frequency > 4 * texels) return;
    table_.resize(static_cast<std::size_t>(frequency * frequency));
    tbb::parallel_for(0LL, frequency, [&](long long j) {
      for (long long i = 0; i < frequency; ++i)
        table_[static_cast<std::size_t>(j * frequency + i)] = lattice_gradient(p, k, frequency, i, j);
    });
  }
  Gradient operator()(long long i, long long j) const {
    if (table_.empty()) return lattice_gradient(p_, k_, frequency_, i, j);
    // Texel centres lie in (0, 1), so i, j are in [0, f]; f wraps to 0 (a compare, not a division).
    const auto wrap = [this](long long v) { return v == frequency_ ? 0 : v; };
    return table_[static_cast<std::size_t>(wrap(j) * frequency_ + wrap(i))];
  }

 private:
  const FbmParams& p_;
  int k_;
  long long frequency_;
  std::vector<Gradient> table_;
};

}  // namespace

void validate(const FbmParams& p) {
  if (p.width < 1 || p.height < 1 || p.width > kMaxFieldSide || p.height > kMaxFieldSide)
    throw Error("noise size must be from 1x1 to " + std::to_string(kMaxFieldSide) + "x" +
                std::to_string(kMaxFieldSide) + ", got " + std::to_string(p.width) + "x" + std::to_string(p.height));
  if (p.octaves < 1 || p.octaves > 24)
    throw Error("noise octaves must be in [1, 24], got " + std::to_string(p.octaves));
  if (!std::isfinite(p.lacunarity) || p.lacunarity < 1.0)
    throw Error("noise lacunarity must be >= 1, got " + format_number(p.lacunarity));
  if (!std::isfinite(p.gain) || p.gain < 0.0 || p.gain > 1.0)
    throw Error("noise gain must be in [0, 1], got " + format_number(p.gain));
  if (p.base_frequency < 1) throw Error("noise base frequency must be >= 1, got " + std::to_string(p.base_frequency));
  if (p.base_frequency * std::pow(p.lacunarity, p.octaves - 1) > 0x1.0p24)
    throw Error("noise top octave is finer than 2^24 cells per tile; use fewer octaves or a smaller lacunarity");
}

double fbm(const FbmParams& p, double x, double y) {
  double sum = 0.0, amplitude = 1.0;
  for (int k = 0; k < p.octaves; ++k) {
    long long frequency = octave_frequency(p, k);
    sum += amplitude * gradient_noise(frequency, x, y, [&](long long i, long long j) {
             return lattice_gradient(p, k, frequency, i, j);
           });
    amplitude *= p.gain;
  }
  return sum;
}

FbmTexture generate_fbm_noise(const FbmParams& p) {
  validate(p);
  ScalarField field{p.width, p.height, std::vector<double>(static_cast<std::size_t>(p.width) * p.height, 0.0)};
  // fbm() at every texel centre, octave by octave: the same sums in the same order, so bit-identical.
  double amplitude = 1.0;
  for (int k = 0; k < p.octaves; ++k) {
    const long long frequency = octave_frequency(p, k);
    const OctaveGradients gradients(p, k, frequency, static_cast<long long>(p.width) * p.height);
    tbb::parallel_for(0, p.height, [&](int y) {
      for (int x = 0; x < p.width; ++x)
        field.values[static_cast<std::size_t>(y) * p.width + x] +=
            amplitude * gradient_noise(frequency, (x + 0.5) / p.width, (y + 0.5) / p.height, gradients);
    });
    amplitude *= p.gain;
  }
  auto [lo, hi] = std::minmax_element(field.values.begin(), field.values.end());
  double raw_min = *lo, raw_max = *hi;
  FbmTexture texture{std::move(field), raw_min, raw_max};
  double range = texture.raw_max - texture.raw_min;
  for (double& v : texture.field.values) v = range > 0.0 ? (v - texture.raw_min) / range : 0.5;
  return texture;
}

ExrMetadata noise_metadata(const FbmParams& p, const FbmTexture& texture) {
  return {
      {"facet:generator", std::string("fbm_gradient_noise")},
      {"facet:seed", std::to_string(p.seed)},
      {"facet:octaves", static_cast<std::int64_t>(p.octaves)},
      {"facet:lacunarity", p.lacunarity},
      {"facet:gain", p.gain},
      {"facet:base_frequency", static_cast<std::int64_t>(p.base_frequency)},
      {"facet:raw_min", texture.raw_min},
      {"facet:raw_max", texture.raw_max},
  };
}

}  // namespace facet::assets
