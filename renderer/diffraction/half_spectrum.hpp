// Reading any bin of a real field's DFT from FFTW's r2c half spectrum, and converting to the
// exp(+i ...) sign of Stam's transform (B.7).
#pragma once

#include <complex>
#include <vector>

namespace facet::diffraction {

// F(j) = sum_x f(x) exp(-i 2 pi j.x / M) of a real M x M field from its r2c output, which keeps
// j_x in [0, M/2]; the other half is F(-j) = conj(F(j)). Indices are taken modulo M.
inline std::complex<double> forward_bin(const std::vector<std::complex<double>>& half, int M, int jx, int jy) {
  const bool mirrored = jx < 0;
  const int sx = mirrored ? -jx : jx;
  const int sy = ((mirrored ? -jy : jy) % M + M) % M;
  const std::complex<double> f = half[static_cast<size_t>(sy) * (M / 2 + 1) + sx];
  return mirrored ? std::conj(f) : f;
}

// The same bin of sum_x f(x) exp(+i 2 pi j.x / M), the sign Stam's P uses: conj(F(j)) for real f.
inline std::complex<double> stam_bin(const std::vector<std::complex<double>>& half, int M, int jx, int jy) {
  return std::conj(forward_bin(half, M, jx, jy));
}

}  // namespace facet::diffraction
