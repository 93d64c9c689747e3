#include "precompute/moment_mips.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/error.hpp"
#include "kernels/shared.hpp"

namespace facet::precompute {

namespace {

// Level-0 texels covered by texel i of a level whose texels span `span` level-0 texels, of `size`.
int coverage(int i, int span, int size) { return std::min((i + 1) * span, size) - i * span; }

// The periodic field's values around texel (x, y): v[dy][dx] = f(x - 1 + dx, y - 1 + dy), wrapped.
struct Neighbourhood {
  int x, y;
  double v[3][3];
};

Neighbourhood neighbourhood(const assets::ScalarField& f, int x, int y) {
  Neighbourhood n{x, y, {}};
  for (int dy = 0; dy < 3; ++dy)
    for (int dx = 0; dx < 3; ++dx) n.v[dy][dx] = f.wrapped(x - 1 + dx, y - 1 + dy);
  return n;
}

// The bilinear reconstruction of the field at (px, py) in texel units (centres at i + 1/2), a point
// of texel (n.x, n.y): its four nearest centres lie in the neighbourhood, which is read once per
// texel instead of wrapping four indices per point.
double bilinear(const Neighbourhood& n, double px, double py) {
  const double sx = px - 0.5, sy = py - 0.5;
  const double fx0 = std::floor(sx), fy0 = std::floor(sy);
  const int i = static_cast<int>(fx0) - (n.x - 1), j = static_cast<int>(fy0) - (n.y - 1);
  const double wx = sx - fx0, wy = sy - fy0;
  const double top = (1 - wx) * n.v[j][i] + wx * n.v[j][i + 1];
  const double bottom = (1 - wx) * n.v[j + 1][i] + wx * n.v[j + 1][i + 1];
  return (1 - wy) * top + wy * bottom;
}

// Variance of the bilinear reconstruction over the cell [x, x+1] x [y, y+1]. It is bilinear on each
// quarter of the cell, so t^2 is biquadratic there and a 2x2 Gauss rule per quarter (nodes 1/4 +- 1/(4
// sqrt 3) and 3/4 +- ... on each axis, equal weights) is exact.
double within_texel_variance(const assets::ScalarField& f, int x, int y) {
  const double d = 0.25 / std::sqrt(3.0);
  const double nodes[4] = {0.25 - d, 0.25 + d, 0.75 - d, 0.75 + d};
  const Neighbourhood n = neighbourhood(f, x, y);
  double samples[16];
  double mean = 0;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) mean += samples[b * 4 + a] = bilinear(n, x + nodes[a], y + nodes[b]);
  mean /= 16;
  double variance = 0;
  for (double s : samples) variance += (s - mean) * (s - mean);
  return variance / 16;
}

}  // namespace

MomentMips build_moment_mips(int width, int height, int channels, std::vector<double> level0) {
  if (width < 1 || height < 1 || channels < 1 || level0.size() != static_cast<std::size_t>(width) * height * channels)
    throw Error("moment MIP maps: level 0 must hold width * height * channels values");
  MomentMips mips{channels, {{width, height, 0}}, std::move(level0)};
  for (int span = 1; mips.levels.back().width > 1 || mips.levels.back().height > 1; span *= 2) {
    const MomentLevel child = mips.levels.back();
    const MomentLevel parent{(child.width + 1) / 2, (child.height + 1) / 2, mips.data.size()};
    mips.levels.push_back(parent);
    mips.data.resize(mips.data.size() + static_cast<std::size_t>(parent.width) * parent.height * channels);
    const int level = static_cast<int>(mips.levels.size()) - 1;
    for (int y = 0; y < parent.height; ++y)
      for (int x = 0; x < parent.width; ++x) {
        // Children weighted by the level-0 texels they cover: the parent is their plain mean.
        double* out = mips.data.data() + parent.offset + (static_cast<std::size_t>(y) * parent.width + x) * channels;
        double total = 0;
        for (int cy = 2 * y; cy < std::min(2 * y + 2, child.height); ++cy)
          for (int cx = 2 * x; cx < std::min(2 * x + 2, child.width); ++cx) {
            const double weight = static_cast<double>(coverage(cx, span, width)) * coverage(cy, span, height);
            const double* in = mips.texel(level - 1, cx, cy);
            for (int c = 0; c < channels; ++c) out[c] += weight * in[c];
            total += weight;
          }
        for (int c = 0; c < channels; ++c) out[c] /= total;
      }
  }
  return mips;
}

std::array<double, kScalarChannels> scalar_moment_texel(const assets::ScalarField& field, int x, int y) {
  const double t = field.at(x, y);
  return {t, t * t, within_texel_variance(field, x, y)};
}

std::vector<double> scalar_moment_level0(const assets::ScalarField& field) {
  std::vector<double> level0(static_cast<std::size_t>(field.width) * field.height * kScalarChannels);
  // 16 bilinear samples per texel: rows in parallel (a 2048² texture is 67 M samples).
  tbb::parallel_for(0, field.height, [&](int y) {
    for (int x = 0; x < field.width; ++x)
      std::ranges::copy(scalar_moment_texel(field, x, y),
                        level0.begin() + (static_cast<std::ptrdiff_t>(y) * field.width + x) * kScalarChannels);
  });
  return level0;
}

MomentMips scalar_moment_mips(const assets::ScalarField& field) {
  return build_moment_mips(field.width, field.height, kScalarChannels, scalar_moment_level0(field));
}

MomentMips lean_moment_mips(const assets::ScalarField& heights, double texel_size) {
  if (!(texel_size > 0.0)) throw Error("LEAN moments: the texel size must be > 0");
  std::vector<double> level0;
  level0.reserve(static_cast<std::size_t>(heights.width) * heights.height * kLeanChannels);
  for (int y = 0; y < heights.height; ++y)
    for (int x = 0; x < heights.width; ++x) {
      const double h = heights.at(x, y);
      const double sx = (heights.wrapped(x + 1, y) - heights.wrapped(x - 1, y)) / (2 * texel_size);
      const double sy = (heights.wrapped(x, y + 1) - heights.wrapped(x, y - 1)) / (2 * texel_size);
      level0.insert(level0.end(), {h, h * h, sx, sy, sx * sx, sy * sy, sx * sy});
    }
  return build_moment_mips(heights.width, heights.height, kLeanChannels, std::move(level0));
}

namespace {

// The trilinear interpolation of the three scalar channels (E[t], E[t^2], within-texel variance).
glm::dvec3 trilinear_scalar_channels(const MomentMips& mips, glm::dvec2 uv, double lod) {
  const int last = static_cast<int>(mips.levels.size()) - 1;
  const double l = std::isnan(lod) ? 0.0 : std::clamp(lod, 0.0, static_cast<double>(last));
  const int l0 = std::min(static_cast<int>(l), last);
  const int l1 = std::min(l0 + 1, last);
  const double f = l - l0;
  auto bilinear_level = [&](int level) {
    // Texel centres of odd-size levels as the GPU places them (shaders/lib/mip_grid.glsl).
    const MomentLevel& m = mips.levels[static_cast<std::size_t>(level)];
    const int span = 1 << level;
    const kernels::f64::MipAxisTaps x = kernels::f64::mip_axis_taps(uv.x, mips.levels[0].width, span, m.width);
    const kernels::f64::MipAxisTaps y = kernels::f64::mip_axis_taps(uv.y, mips.levels[0].height, span, m.height);
    auto at = [&](int i, int j) {
      const double* t = mips.texel(level, i, j);
      return glm::dvec3(t[kScalarMean], t[kScalarSecondMoment], t[kScalarWithinVariance]);
    };
    return (1 - y.w1) * ((1 - x.w1) * at(x.i0, y.i0) + x.w1 * at(x.i1, y.i0)) +
           y.w1 * ((1 - x.w1) * at(x.i0, y.i1) + x.w1 * at(x.i1, y.i1));
  };
  return (1 - f) * bilinear_level(l0) + f * bilinear_level(l1);
}

// Mean and variance from (E[t], E[t^2], within-texel variance): E[t^2] - E[t]^2 of the samples plus
// the variance inside the texels.
MeanVariance to_mean_variance(glm::dvec3 channels) {
  return {channels.x, std::max(channels.y - channels.x * channels.x, 0.0) + channels.z};
}

}  // namespace

MeanVariance lookup_scalar_moments(const MomentMips& mips, glm::dvec2 uv, double lod) {
  return to_mean_variance(trilinear_scalar_channels(mips, uv, lod));
}

MeanVariance lookup_scalar_moments_anisotropic(const MomentMips& mips, glm::dvec2 uv, glm::dvec2 duv_dx,
                                               glm::dvec2 duv_dy, int max_taps) {
  const glm::dvec2 size(mips.levels[0].width, mips.levels[0].height);
  const kernels::f64::AnisotropicFootprint footprint = kernels::f64::anisotropic_footprint(
      duv_dx, duv_dy, size, static_cast<double>(mips.levels.size()), static_cast<double>(std::max(max_taps, 1)));
  const int taps = static_cast<int>(footprint.taps);
  glm::dvec3 sum(0.0);
  for (int k = 0; k < taps; ++k)
    sum += trilinear_scalar_channels(mips, uv + footprint.major * ((k + 0.5) / taps - 0.5), footprint.lod);
  return to_mean_variance(sum / static_cast<double>(taps));
}

}  // namespace facet::precompute
