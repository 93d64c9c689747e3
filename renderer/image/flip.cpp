#include "image/flip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <vector>

#include "image/metrics.hpp"

namespace facet {
namespace {

using Plane = std::vector<double>;

// Linear sRGB (D65) to CIE XYZ, IEC 61966-2-1; glm is column-major, so the rows appear as columns.
const glm::dmat3 kRgbToXyz = glm::transpose(glm::dmat3(0.4124564, 0.3575761, 0.1804375,  //
                                                       0.2126729, 0.7151522, 0.0721750,  //
                                                       0.0193339, 0.1191920, 0.9503041));
const glm::dmat3 kXyzToRgb = glm::inverse(kRgbToXyz);
const glm::dvec3 kWhite = kRgbToXyz * glm::dvec3(1.0);  // the display's white, D65

// Opponent space YCxCz: linear in XYZ, so the CSF filters can be applied in it (paper, sec. 3).
glm::dvec3 xyz_to_ycxcz(glm::dvec3 xyz) {
  const glm::dvec3 n = xyz / kWhite;
  return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

glm::dvec3 ycxcz_to_xyz(glm::dvec3 c) {
  const double y = (c.x + 16.0) / 116.0;
  return glm::dvec3(y + c.y / 500.0, y, y - c.z / 200.0) * kWhite;
}

// CIELAB with the D65 display white.
glm::dvec3 xyz_to_lab(glm::dvec3 xyz) {
  const auto f = [](double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const glm::dvec3 n = xyz / kWhite;
  return {116.0 * f(n.y) - 16.0, 500.0 * (f(n.x) - f(n.y)), 200.0 * (f(n.y) - f(n.z))};
}

// Hunt effect: chroma is perceived weaker in dark colours, a' = 0.01·L·a, b' = 0.01·L·b.
glm::dvec3 hunt_lab(glm::dvec3 linear_rgb) {
  const glm::dvec3 lab = xyz_to_lab(kRgbToXyz * linear_rgb);
  return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z};
}

// HyAB distance: city-block in lightness, Euclidean in chroma.
double hyab(glm::dvec3 a, glm::dvec3 b) { return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z); }

// One term c·g(x)·g(y) of a separable 2D kernel, with the 1D taps g at offsets -radius..radius.
struct SeparableTerm {
  double weight;
  std::vector<double> taps;
};

// Row filter with `along_x`, then column filter with `along_y`; borders repeat the edge pixel (as
// the authors' reference code does).
Plane filter_xy(const Plane& in, int width, int height, const std::vector<double>& along_x,
                const std::vector<double>& along_y) {
  Plane rows(in.size()), out(in.size());
  const int rx = static_cast<int>(along_x.size() / 2), ry = static_cast<int>(along_y.size() / 2);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int k = -rx; k <= rx; ++k) sum += along_x[k + rx] * in[y * width + std::clamp(x + k, 0, width - 1)];
      rows[y * width + x] = sum;
    }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int k = -ry; k <= ry; ++k) sum += along_y[k + ry] * rows[std::clamp(y + k, 0, height - 1) * width + x];
      out[y * width + x] = sum;
    }
  return out;
}

// Sum of separable terms, each applied with clamp-to-edge borders.
Plane filter(const Plane& in, int width, int height, const std::vector<SeparableTerm>& kernel) {
  Plane out(in.size(), 0.0);
  for (const SeparableTerm& term : kernel) {
    const Plane part = filter_xy(in, width, height, term.taps, term.taps);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += term.weight * part[i];
  }
  return out;
}

// Contrast sensitivity as spatial kernels (the paper's CSF parameters a_i, b_i): Σ a_i sqrt(π/b_i) exp(-π² x²/b_i),
// x in degrees, normalised to sum 1. Index 0: achromatic, 1: red-green, 2: blue-yellow.
std::array<std::vector<SeparableTerm>, 3> csf_kernels(double ppd) {
  const double a[3][2] = {{1.0, 0.0}, {1.0, 0.0}, {34.1, 13.5}};
  const double b[3][2] = {{0.0047, 1e-5}, {0.0053, 1e-5}, {0.04, 0.025}};
  // One radius for all three: three standard deviations of the widest term (b = 0.04).
  const int radius =
      static_cast<int>(std::ceil(3.0 * std::sqrt(0.04 / (2.0 * std::numbers::pi * std::numbers::pi)) * ppd));
  std::array<std::vector<SeparableTerm>, 3> kernels;
  for (int c = 0; c < 3; ++c) {
    double total = 0.0;
    for (int i = 0; i < 2; ++i) {
      if (a[c][i] == 0.0) continue;
      SeparableTerm term{a[c][i] * std::sqrt(std::numbers::pi / b[c][i]), std::vector<double>(2 * radius + 1)};
      double taps_sum = 0.0;
      for (int k = -radius; k <= radius; ++k) {
        const double x = k / ppd;
        taps_sum += term.taps[k + radius] = std::exp(-std::numbers::pi * std::numbers::pi * x * x / b[c][i]);
      }
      total += term.weight * taps_sum * taps_sum;
      kernels[c].push_back(term);
    }
    for (SeparableTerm& term : kernels[c]) term.weight /= total;
  }
  return kernels;
}

// Colour part: CSF-filtered images compared in Hunt-adjusted CIELAB with HyAB, then redistributed
// so that the lower 40% of the maximum (green vs blue) difference fills 95% of [0,1].
Plane colour_difference(const Image& test, const Image& reference, double ppd) {
  const int width = test.width, height = test.height;
  const std::size_t n = test.pixel_count();
  const auto kernels = csf_kernels(ppd);
  std::array<Plane, 3> filtered[2];
  const Image* images[2] = {&test, &reference};
  for (int i = 0; i < 2; ++i) {
    std::array<Plane, 3> opponent;
    for (Plane& p : opponent) p.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
      const glm::dvec3 c = xyz_to_ycxcz(kRgbToXyz * glm::clamp(glm::dvec3(images[i]->at(p)), 0.0, 1.0));
      for (int k = 0; k < 3; ++k) opponent[k][p] = c[k];
    }
    for (int k = 0; k < 3; ++k) filtered[i][k] = filter(opponent[k], width, height, kernels[k]);
  }
  constexpr double q_c = 0.7, p_c = 0.4, p_t = 0.95;
  const double c_max = std::pow(hyab(hunt_lab({0.0, 1.0, 0.0}), hunt_lab({0.0, 0.0, 1.0})), q_c);
  Plane error(n);
  for (std::size_t p = 0; p < n; ++p) {
    glm::dvec3 lab[2];
    for (int i = 0; i < 2; ++i) {
      const glm::dvec3 ycxcz(filtered[i][0][p], filtered[i][1][p], filtered[i][2][p]);
      lab[i] = hunt_lab(glm::clamp(kXyzToRgb * ycxcz_to_xyz(ycxcz), 0.0, 1.0));
    }
    const double e = std::pow(hyab(lab[0], lab[1]), q_c);
    error[p] =
        e < p_c * c_max ? p_t / (p_c * c_max) * e : p_t + (e - p_c * c_max) / (c_max - p_c * c_max) * (1.0 - p_t);
  }
  return error;
}

// 1D factors of the feature kernels, σ = 0.5·0.082°·ppd (w = 0.082° is the peak-to-trough width of the edge detector).
// The 2D kernels (edge: -x·g, point: (x²/σ² - 1)·g, with positive and negative weights each normalised to ±1) are
// products of these with the normalised Gaussian along the other axis.
struct FeatureTaps {
  std::vector<double> gaussian, edge, point;
};

FeatureTaps feature_taps(double ppd) {
  const double sigma = 0.5 * 0.082 * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  FeatureTaps taps;
  for (int k = -radius; k <= radius; ++k) {
    const double g = std::exp(-k * k / (2.0 * sigma * sigma));
    taps.gaussian.push_back(g);
    taps.edge.push_back(-k * g);
    taps.point.push_back((k * k / (sigma * sigma) - 1.0) * g);
  }
  const auto normalise_signed = [](std::vector<double>& v) {
    double positive = 0.0, negative = 0.0;
    for (double w : v) (w > 0 ? positive : negative) += w;
    for (double& w : v) w /= w > 0 ? positive : -negative;
  };
  double sum = 0.0;
  for (double g : taps.gaussian) sum += g;
  for (double& g : taps.gaussian) g /= sum;
  normalise_signed(taps.edge);
  normalise_signed(taps.point);
  return taps;
}

// Feature part: edge and point responses of the normalised achromatic channel Y/Y_n of the
// unfiltered images; ΔF = (max(|Δ|edge||, |Δ|point||)/√2)^q_f, q_f = 0.5.
Plane feature_difference(const Image& test, const Image& reference, double ppd) {
  const int width = test.width, height = test.height;
  const FeatureTaps taps = feature_taps(ppd);
  Plane magnitudes[2][2];  // [image][edge, point]
  const Image* images[2] = {&test, &reference};
  for (int i = 0; i < 2; ++i) {
    Plane y(test.pixel_count());
    for (std::size_t p = 0; p < y.size(); ++p)
      y[p] = (kRgbToXyz * glm::clamp(glm::dvec3(images[i]->at(p)), 0.0, 1.0)).y / kWhite.y;
    const std::vector<double>* detectors[2] = {&taps.edge, &taps.point};
    for (int d = 0; d < 2; ++d) {
      const Plane gx = filter_xy(y, width, height, *detectors[d], taps.gaussian);
      const Plane gy = filter_xy(y, width, height, taps.gaussian, *detectors[d]);
      magnitudes[i][d].resize(y.size());
      for (std::size_t p = 0; p < y.size(); ++p) magnitudes[i][d][p] = std::hypot(gx[p], gy[p]);
    }
  }
  Plane difference(test.pixel_count());
  for (std::size_t p = 0; p < difference.size(); ++p) {
    const double largest = std::max(std::abs(magnitudes[0][0][p] - magnitudes[1][0][p]),
                                    std::abs(magnitudes[0][1][p] - magnitudes[1][1][p]));
    difference[p] = std::sqrt(largest / std::sqrt(2.0));
  }
  return difference;
}

}  // namespace

ScalarImage flip_map(const Image& test, const Image& reference, double pixels_per_degree) {
  check_comparable(test, reference);
  const Plane colour = colour_difference(test, reference, pixels_per_degree);
  const Plane feature = feature_difference(test, reference, pixels_per_degree);
  ScalarImage map(test.width, test.height);
  // Features sharpen the colour error: ΔE = ΔE_c^(1 - ΔF).
  for (std::size_t p = 0; p < map.pixel_count(); ++p)
    map.values[p] = static_cast<float>(std::pow(colour[p], 1.0 - feature[p]));
  return map;
}

double flip(const Image& test, const Image& reference, double pixels_per_degree) {
  const ScalarImage map = flip_map(test, reference, pixels_per_degree);
  double sum = 0.0;
  for (float v : map.values) sum += v;
  return sum / static_cast<double>(map.pixel_count());
}

}  // namespace facet
