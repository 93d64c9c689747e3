// The exact transform made affordable for the reference renderer: every band bin of
// p_j(x) = (1/M^2) sum_x exp(i x h(x)) exp(+i alpha_j.x) (h normalised, x = k w h_s) as a function of
// the one scalar x, interpolated in x by piecewise Chebyshev polynomials through exact values
// (ExactTransform::bins at the Chebyshev nodes). p_j is a sum of exp(i x s) with |s| <= 1 and
// weights of total modulus 1, so every derivative of its real and imaginary parts is bounded by 1
// and the interpolation remainder is at most 2 (L/4)^n / n! per part on a piece of length L with
// n nodes (docs/diffraction.md, "Exact reference"). No Taylor series anywhere.
#pragma once

#include <complex>
#include <vector>

#include "diffraction/diffraction_eval.hpp"
#include "diffraction/exact_transform.hpp"
#include "diffraction/spectral_tables.hpp"
#include "scene/grating/grating.hpp"

namespace facet::diffraction {

class ChebyshevTransform {
 public:
  static constexpr int kNodes = 16;         // n per piece
  static constexpr double kMaxPiece = 4.0;  // L: 2 (L/4)^16 / 16! = 9.6e-14 per part

  // Covers x in [-x_max, 0] for the band |j_x|, |j_y| <= tables.J (x_max = tables.x_max by default).
  ChebyshevTransform(const Grating& grating, const SpectralTables& tables, double x_max = 0.0);

  // |p_j(x) - interpolant| <= this for every bin and every x in range (both parts together).
  double error_bound() const;
  double x_max() const { return x_max_; }

  // The interpolant at one x: barycentric weights computed once, then one dot product per bin.
  class AtX {
   public:
    std::complex<double> bin(int jx, int jy) const;

   private:
    friend class ChebyshevTransform;
    const ChebyshevTransform* owner_;
    int piece_;
    int exact_node_;  // >= 0 when x falls on a node
    double weights_[kNodes];
  };
  AtX at(double x) const;

  // The BRDF with P from the interpolated exact bins (throws facet::Error if k w h_s is out of range).
  DiffractionResult evaluate(const DiffractionQuery& q) const;

 private:
  const SpectralTables* tables_;
  double x_max_;
  int pieces_;
  double piece_length_;
  int J_;
  // values_[((piece * bins) + bin) * kNodes + node], bin = (jy + J) (2J + 1) + jx + J.
  std::vector<std::complex<double>> values_;
};

}  // namespace facet::diffraction
