#include "diffraction/chebyshev_transform.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/error.hpp"

namespace facet::diffraction {

namespace {

using std::numbers::pi;

// Chebyshev points of the first kind on [-1, 1] and their barycentric weights (Berrut and
// Trefethen 2004, eq. 5.3): t_i = cos((2i+1) pi / 2n), w_i = (-1)^i sin((2i+1) pi / 2n).
double node(int i) { return std::cos((2 * i + 1) * pi / (2 * ChebyshevTransform::kNodes)); }
double barycentric_weight(int i) {
  return (i % 2 == 0 ? 1.0 : -1.0) * std::sin((2 * i + 1) * pi / (2 * ChebyshevTransform::kNodes));
}

}  // namespace

ChebyshevTransform::ChebyshevTransform(const Grating& grating, const SpectralTables& tables, double x_max)
    : tables_(&tables), x_max_(x_max > 0.0 ? x_max : tables.x_max), J_(tables.J) {
  pieces_ = std::max(1, static_cast<int>(std::ceil(x_max_ / kMaxPiece)));
  piece_length_ = x_max_ / pieces_;
  const ExactTransform exact(grating, tables);
  const int side = 2 * J_ + 1;
  const size_t bins = static_cast<size_t>(side) * side;
  values_.resize(static_cast<size_t>(pieces_) * bins * kNodes);
  for (int p = 0; p < pieces_; ++p) {
    const double a = -x_max_ + p * piece_length_;
    for (int i = 0; i < kNodes; ++i) {
      const ExactTransform::Bins b = exact.bins(a + 0.5 * piece_length_ * (node(i) + 1.0));
      for (int jy = -J_; jy <= J_; ++jy)
        for (int jx = -J_; jx <= J_; ++jx) {
          const size_t bin = static_cast<size_t>(jy + J_) * side + (jx + J_);
          values_[(p * bins + bin) * kNodes + i] = b.at(jx, jy);
        }
    }
  }
}

double ChebyshevTransform::error_bound() const {
  // 2 (L/4)^n / n! per part (the node polynomial of Chebyshev points is 2 (L/4)^n at most), sqrt 2 for both.
  double bound = 2.0 * std::sqrt(2.0);
  for (int k = 1; k <= kNodes; ++k) bound *= (piece_length_ / 4.0) / k;
  return bound;
}

ChebyshevTransform::AtX ChebyshevTransform::at(double x) const {
  if (!(x >= -x_max_ * (1.0 + 1e-12) && x <= 0.0))
    throw Error("exact diffraction: k w h_s = " + std::to_string(x) + " lies outside the interpolated range [" +
                std::to_string(-x_max_) + ", 0]");
  AtX r;
  r.owner_ = this;
  r.piece_ = std::min(pieces_ - 1, static_cast<int>((x + x_max_) / piece_length_));
  const double a = -x_max_ + r.piece_ * piece_length_;
  const double t = std::clamp(2.0 * (x - a) / piece_length_ - 1.0, -1.0, 1.0);
  r.exact_node_ = -1;
  double sum = 0.0;
  for (int i = 0; i < kNodes; ++i) {
    const double d = t - node(i);
    if (d == 0.0) {
      r.exact_node_ = i;
      return r;
    }
    r.weights_[i] = barycentric_weight(i) / d;
    sum += r.weights_[i];
  }
  for (double& w : r.weights_) w /= sum;  // the second barycentric form: p = sum w_i f_i / sum w_i
  return r;
}

std::complex<double> ChebyshevTransform::AtX::bin(int jx, int jy) const {
  const int J = owner_->J_, side = 2 * J + 1;
  if (std::abs(jx) > J || std::abs(jy) > J) return 0.0;
  const size_t bins = static_cast<size_t>(side) * side;
  const std::complex<double>* f =
      &owner_->values_[(piece_ * bins + static_cast<size_t>(jy + J) * side + (jx + J)) * kNodes];
  if (exact_node_ >= 0) return f[exact_node_];
  std::complex<double> sum = 0.0;
  for (int i = 0; i < kNodes; ++i) sum += weights_[i] * f[i];
  return sum;
}

DiffractionResult ChebyshevTransform::evaluate(const DiffractionQuery& q) const {
  const AtX p = at(2.0 * pi / q.lambda_nm * exact_phase_w(q) * tables_->hs_nm);
  return evaluate_from_bins(*tables_, q, [&](int jx, int jy) { return p.bin(jx, jy); });
}

}  // namespace facet::diffraction
