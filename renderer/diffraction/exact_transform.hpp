// The exact reference: P computed without the Taylor expansion, as the DFT of
// p = exp(i k w (h - mean)) itself (two real FFTs in double per (k, w)), then windowed like the
// tables. Slow (O(M^2 log M) per distinct k w) and meant for tests and `--exact`.
#pragma once

#include <complex>
#include <vector>

#include "diffraction/diffraction_eval.hpp"
#include "diffraction/spectral_tables.hpp"
#include "scene/grating/grating.hpp"

namespace facet::diffraction {

class ExactTransform {
 public:
  // `tables` supplies the band, the window and the units (its coefficients are not used).
  ExactTransform(const Grating& grating, const SpectralTables& tables);

  DiffractionResult evaluate(const DiffractionQuery& q) const;

  // The DFT of p = exp(i phase_per_unit (h - mean) / h_s) with Stam's sign, divided by M^2.
  struct Bins {
    std::vector<std::complex<double>> cos_half, sin_half;  // r2c spectra of Re p and Im p
    int M;
    std::complex<double> at(int jx, int jy) const;
  };
  Bins bins(double phase_per_unit) const;

 private:
  const SpectralTables* tables_;
  int samples_;
  std::vector<double> normalised_;  // (h - mean) / h_s
};

}  // namespace facet::diffraction
