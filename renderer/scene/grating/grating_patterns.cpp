#include "scene/grating/grating_patterns.hpp"

#include <cmath>
#include <functional>
#include <numbers>

namespace facet::diffraction {

namespace {

// Samples sit at x = i * spacing (i = 0..samples-1), the same positions the DFT assumes.
std::vector<double> sample_patch(PatchGrid grid, const std::function<double(double, double)>& height) {
  std::vector<double> h(static_cast<size_t>(grid.samples) * grid.samples);
  for (int iy = 0; iy < grid.samples; ++iy)
    for (int ix = 0; ix < grid.samples; ++ix)
      h[static_cast<size_t>(iy) * grid.samples + ix] = height(ix * grid.sample_nm, iy * grid.sample_nm);
  return h;
}

double fraction(double t) { return t - std::floor(t); }

}  // namespace

std::vector<double> sinusoid_heights(PatchGrid grid, double period_nm, double amplitude_nm) {
  return sample_patch(
      grid, [=](double x, double) { return amplitude_nm * std::sin((2.0 * std::numbers::pi) * x / period_nm); });
}

std::vector<double> rectangular_heights(PatchGrid grid, double period_nm, double amplitude_nm, double duty) {
  return sample_patch(grid, [=](double x, double) {
    // Samples on an edge go to the period that starts there, whatever the rounding of x / period.
    return fraction(x / period_nm + 1e-9) < duty ? amplitude_nm : -amplitude_nm;
  });
}

std::vector<double> crossed_heights(PatchGrid grid, double period_x_nm, double period_y_nm, double amplitude_nm) {
  return sample_patch(grid, [=](double x, double y) {
    return 0.5 * amplitude_nm *
           (std::sin((2.0 * std::numbers::pi) * x / period_x_nm) +
            std::sin((2.0 * std::numbers::pi) * y / period_y_nm));
  });
}

std::vector<double> finger_heights(PatchGrid grid, double period_nm, double amplitude_nm, double duty,
                                   double finger_length_nm) {
  return sample_patch(grid, [=](double x, double y) {
    const double row = std::floor(y / finger_length_nm);
    const double shift = std::fmod(row, 2.0) == 0.0 ? 0.0 : 0.5;
    // Raised-cosine ridge of width duty * period, centred in its period.
    const double across = (fraction(x / period_nm + shift) - 0.5) / duty;
    const double ridge = std::abs(across) < 0.5 ? std::pow(std::cos(std::numbers::pi * across), 2) : 0.0;
    // Each finger tapers to nothing at both ends, like the overlapping cells of a snake scale.
    const double along = std::sin(std::numbers::pi * fraction(y / finger_length_nm));
    return amplitude_nm * ridge * along * along;
  });
}

}  // namespace facet::diffraction
