#include "assets/fbm_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

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

// Dot product of the lattice gradient at corner (i, j) of octave k with the offset (dx, dy).
double corner(const FbmParams& p, int k, long long frequency, long long i, long long j, double dx, double dy) {
  auto wrap = [frequency](long long v) {
    return static_cast<std::uint64_t>(((v % frequency) + frequency) % frequency);
  };
  std::uint64_t h = splitmix64(splitmix64(splitmix64(p.seed ^ splitmix64(static_cast<std::uint64_t>(k))) ^ wrap(i)) ^
                               (wrap(j) << 32));
  double angle = 2.0 * std::numbers::pi * static_cast<double>(h >> 11) * 0x1.0p-53;
  return std::cos(angle) * dx + std::sin(angle) * dy;
}

double gradient_noise(const FbmParams& p, int k, long long frequency, double x, double y) {
  double fx = x * static_cast<double>(frequency), fy = y * static_cast<double>(frequency);
  long long i = static_cast<long long>(std::floor(fx)), j = static_cast<long long>(std::floor(fy));
  double dx = fx - static_cast<double>(i), dy = fy - static_cast<double>(j);
  double n00 = corner(p, k, frequency, i, j, dx, dy);
  double n10 = corner(p, k, frequency, i + 1, j, dx - 1.0, dy);
  double n01 = corner(p, k, frequency, i, j + 1, dx, dy - 1.0);
  double n11 = corner(p, k, frequency, i + 1, j + 1, dx - 1.0, dy - 1.0);
  double u = fade(dx), v = fade(dy);
  return (1.0 - v) * ((1.0 - u) * n00 + u * n10) + v * ((1.0 - u) * n01 + u * n11);
}

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
    sum += amplitude * gradient_noise(p, k, octave_frequency(p, k), x, y);
    amplitude *= p.gain;
  }
  return sum;
}

FbmTexture generate_fbm_noise(const FbmParams& p) {
  validate(p);
  ScalarField field{p.width, p.height, std::vector<double>(static_cast<std::size_t>(p.width) * p.height)};
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      field.values[static_cast<std::size_t>(y) * p.width + x] = fbm(p, (x + 0.5) / p.width, (y + 0.5) / p.height);
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
