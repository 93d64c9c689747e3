// 2-D real <-> half-complex DFTs in double (FFTW), unnormalised like FFTW:
// inverse(forward(x)) = width·height·x.
//
// FFTW's planner is not thread-safe, so plan creation and destruction are serialised behind one
// mutex; the transforms themselves run concurrently. Plans use FFTW_ESTIMATE, which makes the same
// plan (and so the same bytes) on every run, unlike FFTW_MEASURE.
#pragma once

#include <complex>
#include <vector>

struct fftw_plan_s;  // FFTW's opaque plan (fftw_plan is fftw_plan_s*)

namespace facet::assets {

class RealFft2d {
 public:
  RealFft2d(int width, int height);
  ~RealFft2d();
  RealFft2d(const RealFft2d&) = delete;
  RealFft2d& operator=(const RealFft2d&) = delete;

  // Row-major real grid (width × height) -> height × (width/2 + 1) spectrum, and back.
  std::vector<std::complex<double>> forward(const std::vector<double>& grid) const;
  std::vector<double> inverse(std::vector<std::complex<double>> spectrum) const;

  int spectrum_width() const { return width_ / 2 + 1; }

 private:
  int width_, height_;
  fftw_plan_s* forward_plan_;
  fftw_plan_s* inverse_plan_;
};

}  // namespace facet::assets
