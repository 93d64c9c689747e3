// Procedural height fields of one grating patch, in nm. Each pattern is periodic on the patch,
// so tiling it leaves no seam.
#pragma once

#include <vector>

namespace facet::diffraction {

struct PatchGrid {
  int samples;       // samples x samples
  double sample_nm;  // spacing
};

// h = a sin(2 pi x / period): a thin sinusoidal phase grating along x.
std::vector<double> sinusoid_heights(PatchGrid grid, double period_nm, double amplitude_nm);
// Binary grating along x: +a on the first `duty` of each period, -a elsewhere.
std::vector<double> rectangular_heights(PatchGrid grid, double period_nm, double amplitude_nm, double duty);
// Sum of two sinusoids along x and y, each of amplitude a / 2 (peak a).
std::vector<double> crossed_heights(PatchGrid grid, double period_x_nm, double period_y_nm, double amplitude_nm);
// Snake-scale-like ridges: smooth ridges across x (period along x), broken into fingers of
// length `finger_length_nm` along y, each row of fingers shifted by half a period.
std::vector<double> finger_heights(PatchGrid grid, double period_nm, double amplitude_nm, double duty,
                                   double finger_length_nm);

}  // namespace facet::diffraction
