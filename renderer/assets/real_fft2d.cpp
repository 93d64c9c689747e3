#include "assets/real_fft2d.hpp"

#include <fftw3.h>

#include <mutex>

namespace facet::assets {

namespace {

std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

RealFft2d::RealFft2d(int width, int height) : width_(width), height_(height) {
  std::size_t n = static_cast<std::size_t>(width) * height;
  std::size_t n_spectrum = static_cast<std::size_t>(height) * spectrum_width();
  // These arrays serve planning only. FFTW_UNALIGNED lets the plans run on any std::vector's
  // storage through the new-array execute functions.
  double* real = fftw_alloc_real(n);
  fftw_complex* complex = fftw_alloc_complex(n_spectrum);
  std::lock_guard lock(planner_mutex());
  forward_plan_ = fftw_plan_dft_r2c_2d(height, width, real, complex, FFTW_ESTIMATE | FFTW_UNALIGNED);
  inverse_plan_ = fftw_plan_dft_c2r_2d(height, width, complex, real, FFTW_ESTIMATE | FFTW_UNALIGNED);
  fftw_free(real);
  fftw_free(complex);
}

RealFft2d::~RealFft2d() {
  std::lock_guard lock(planner_mutex());
  fftw_destroy_plan(forward_plan_);
  fftw_destroy_plan(inverse_plan_);
}

std::vector<std::complex<double>> RealFft2d::forward(const std::vector<double>& grid) const {
  std::vector<double> input = grid;  // r2c may not overwrite its input, but FFTW's API is non-const
  std::vector<std::complex<double>> spectrum(static_cast<std::size_t>(height_) * spectrum_width());
  fftw_execute_dft_r2c(forward_plan_, input.data(), reinterpret_cast<fftw_complex*>(spectrum.data()));
  return spectrum;
}

std::vector<double> RealFft2d::inverse(std::vector<std::complex<double>> spectrum) const {
  // c2r destroys its input: `spectrum` is taken by value.
  std::vector<double> grid(static_cast<std::size_t>(width_) * height_);
  fftw_execute_dft_c2r(inverse_plan_, reinterpret_cast<fftw_complex*>(spectrum.data()), grid.data());
  return grid;
}

}  // namespace facet::assets
