#include "diffraction/exact_transform.hpp"

#include <cmath>
#include <numbers>

#include "assets/real_fft2d.hpp"
#include "diffraction/half_spectrum.hpp"

namespace facet::diffraction {

ExactTransform::ExactTransform(const Grating& grating, const SpectralTables& tables)
    : tables_(&tables), samples_(grating.samples), normalised_(grating.height_nm.size()) {
  for (size_t i = 0; i < normalised_.size(); ++i)
    normalised_[i] = (grating.height_nm[i] - tables.mean_nm) / tables.hs_nm;
}

ExactTransform::Bins ExactTransform::bins(double phase_per_unit) const {
  // p = cos + i sin of the phase; both parts are real, so each is one r2c transform and
  // P(j) = stam(cos)(j) + i stam(sin)(j).
  std::vector<double> c(normalised_.size()), s(normalised_.size());
  for (size_t i = 0; i < normalised_.size(); ++i) {
    c[i] = std::cos(phase_per_unit * normalised_[i]);
    s[i] = std::sin(phase_per_unit * normalised_[i]);
  }
  assets::RealFft2d fft(samples_, samples_);
  return {fft.forward(c), fft.forward(s), samples_};
}

std::complex<double> ExactTransform::Bins::at(int jx, int jy) const {
  const double scale = 1.0 / (static_cast<double>(M) * M);
  return scale * (stam_bin(cos_half, M, jx, jy) + std::complex<double>(0.0, 1.0) * stam_bin(sin_half, M, jx, jy));
}

DiffractionResult ExactTransform::evaluate(const DiffractionQuery& q) const {
  const Bins p = bins((2.0 * std::numbers::pi) / q.lambda_nm * exact_phase_w(q) * tables_->hs_nm);
  return evaluate_from_bins(*tables_, q, [&](int jx, int jy) { return p.at(jx, jy); });
}

}  // namespace facet::diffraction
