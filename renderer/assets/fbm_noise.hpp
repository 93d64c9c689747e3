// Tileable fBm (fractional Brownian motion) textures built from 2-D gradient noise.
//
// Octave k is gradient noise on a periodic integer lattice of f_k = round(f_0 λ^k) cells per tile
// (so every octave, and the sum, tiles exactly), with amplitude g^k:
//   fbm(x, y) = Σ_{k<octaves} g^k · gradient_noise_k(f_k x, f_k y),   (x, y) ∈ [0, 1)² per tile.
// Lattice gradients are unit vectors at angles from a hash (splitmix64) of (seed, k, i mod f_k,
// j mod f_k); corners are blended with the quintic fade 6t⁵ − 15t⁴ + 10t³ (C² across cells).
// The texture samples texel centres ((i + ½)/W, (j + ½)/H) and is then mapped affinely onto [0, 1]
// (its minimum to 0, maximum to 1; a constant texture becomes 0.5). docs/assets.md.
#pragma once

#include <cstdint>

#include "assets/scalar_field.hpp"

namespace facet::assets {

struct FbmParams {
  int width = 256, height = 256;
  int octaves = 6;
  double lacunarity = 2.0;  // λ ≥ 1
  double gain = 0.5;        // g in [0, 1]
  int base_frequency = 4;   // f_0, lattice cells per tile, ≥ 1
  std::uint64_t seed = 1;
};

// Throws facet::Error (one line) for sizes < 1, octaves outside [1, 24], λ < 1, g outside [0, 1],
// f_0 < 1, non-finite values, or a top octave finer than 2^24 cells per tile.
void validate(const FbmParams& params);

// The raw (unnormalised) sum above at tile coordinates (x, y); periodic with period 1.
double fbm(const FbmParams& params, double x, double y);

// The [0, 1] texture and the raw range that was mapped onto it.
struct FbmTexture {
  ScalarField field;
  double raw_min = 0.0, raw_max = 0.0;
};
FbmTexture generate_fbm_noise(const FbmParams& params);

// "facet:generator", "facet:seed", "facet:octaves", "facet:lacunarity", "facet:gain",
// "facet:base_frequency", and the affine map applied: "facet:raw_min", "facet:raw_max".
ExrMetadata noise_metadata(const FbmParams& params, const FbmTexture& texture);

}  // namespace facet::assets
