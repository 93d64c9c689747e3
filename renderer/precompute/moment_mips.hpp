// MIP chains of moments of a periodic texture, box-filtered 2x2 (docs/colormap_filtering.md):
// the mean and variance of a colour-mapped scalar texture over a pixel footprint (Heitz et al. 2013),
// and LEAN-style height and slope moments of a height field. Odd sizes: level l + 1 has
// ceil(size_l / 2) texels and its last texel covers what is left (one child), so every texel of every
// level is the plain mean over the level-0 texels it covers.
#pragma once

#include <array>

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "assets/scalar_field.hpp"

namespace facet::precompute {

struct MomentLevel {
  int width = 0, height = 0;
  std::size_t offset = 0;  // of texel (0, 0), in values (texel index * channels)
};

struct MomentMips {
  int channels = 0;
  std::vector<MomentLevel> levels;  // level 0 first, down to 1x1
  std::vector<double> data;         // level by level, row-major, `channels` values per texel

  const double* texel(int level, int x, int y) const {
    const MomentLevel& l = levels[static_cast<std::size_t>(level)];
    return data.data() + l.offset + (static_cast<std::size_t>(y) * l.width + x) * channels;
  }
  // The same values as floats, offsets unchanged: one buffer for upload.
  std::vector<float> flatten_f32() const { return std::vector<float>(data.begin(), data.end()); }
};

// Box-filtered chain of any per-texel moments: level0 holds width * height * channels values.
MomentMips build_moment_mips(int width, int height, int channels, std::vector<double> level0);

// Channels of scalar_moment_mips: t, t^2 (of the texel samples) and the within-texel variance, the
// variance of the bilinear reconstruction of t over the texel's own cell (centre +- half a texel).
enum ScalarMomentChannel { kScalarMean = 0, kScalarSecondMoment = 1, kScalarWithinVariance = 2, kScalarChannels = 3 };
MomentMips scalar_moment_mips(const assets::ScalarField& field);
// Level 0 of scalar_moment_mips alone (kScalarChannels values per texel).
std::vector<double> scalar_moment_level0(const assets::ScalarField& field);
// One texel of it, texel (x, y): what a GPU-built chain writes in place (gpu/texture_upload.cpp).
std::array<double, kScalarChannels> scalar_moment_texel(const assets::ScalarField& field, int x, int y);

// Channels of lean_moment_mips: h, h^2, s_x, s_y, s_x^2, s_y^2, s_x s_y with the slopes by central
// differences, s_x = (h[x+1] - h[x-1]) / (2 texel_size) (the slope of the bilinear surface at the texel
// centre, averaged over its two sides).
enum LeanMomentChannel { kLeanH = 0, kLeanH2, kLeanSx, kLeanSy, kLeanSx2, kLeanSy2, kLeanSxSy, kLeanChannels };
MomentMips lean_moment_mips(const assets::ScalarField& heights, double texel_size);

struct MeanVariance {
  double mean = 0.0;
  double variance = 0.0;
};

// Mean and variance of t over a footprint of 2^lod level-0 texels at uv (period 1, texel centres at
// (i + 1/2)/W as in the scene): trilinear interpolation of the scalar moments between levels
// floor(lod) and floor(lod) + 1 (lod clamped to the chain), variance = E[t^2] - E[t]^2 of the samples
// plus the interpolated within-texel variance.
MeanVariance lookup_scalar_moments(const MomentMips& mips, glm::dvec2 uv, double lod);

// The same over an anisotropic footprint with uv axes duv_dx, duv_dy: the taps and level of
// anisotropic_footprint (shaders/lib/texture_footprint.glsl, as the GPU), their moments combined as a
// mixture (mean of the taps' E[t], E[t^2] and within-texel variances).
MeanVariance lookup_scalar_moments_anisotropic(const MomentMips& mips, glm::dvec2 uv, glm::dvec2 duv_dx,
                                               glm::dvec2 duv_dy, int max_taps);

}  // namespace facet::precompute
