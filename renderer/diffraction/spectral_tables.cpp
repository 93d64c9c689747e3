#include "diffraction/spectral_tables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/real_fft2d.hpp"
#include "common/error.hpp"
#include "diffraction/half_spectrum.hpp"
#include "kernels/shared.hpp"

namespace facet::diffraction {

namespace {

constexpr int kMaxTerms = 64;

void validate(const TableRange& range) {
  if (!(range.lambda_min_nm > 0.0 && range.lambda_max_nm >= range.lambda_min_nm))
    throw Error("diffraction tables: need 0 < lambda_min_nm <= lambda_max_nm");
  if (!(range.w_max > 0.0 && range.w_max <= 2.0)) throw Error("diffraction tables: w_max must lie in (0, 2]");
  if (!(range.tolerance > 0.0 && range.tolerance < 1.0))
    throw Error("diffraction tables: tolerance must lie in (0, 1)");
  if (range.terms < 0 || range.terms > kMaxTerms)
    throw Error("diffraction tables: terms must lie in [0, " + std::to_string(kMaxTerms) + "]");
}

}  // namespace

int taylor_term_count(double x_max, double tolerance) {
  double term = 1.0;  // x^N / N!
  for (int N = 1; N <= kMaxTerms; ++N) {
    term *= x_max / N;
    if (term <= tolerance) return N;
  }
  throw Error("diffraction tables: k w h = " + std::to_string(x_max) + " needs more than " + std::to_string(kMaxTerms) +
              " Taylor terms; use a larger tolerance or a lower grating");
}

int window_radius(double period_nm, double sigma_nm, double tolerance) {
  const double reach = std::sqrt(2.0 * std::log(1.0 / tolerance)) * period_nm / ((2.0 * std::numbers::pi) * sigma_nm);
  return std::max(0, static_cast<int>(std::ceil(reach - 0.5)));
}

std::vector<glm::vec2> SpectralTables::coefficients_f32() const {
  std::vector<glm::vec2> out(coefficients.size());
  std::transform(coefficients.begin(), coefficients.end(), out.begin(),
                 [](std::complex<double> c) { return glm::vec2(c.real(), c.imag()); });
  return out;
}

SpectralTables build_spectral_tables(const Grating& grating, const TableRange& range) {
  validate(range);
  const int M = grating.samples;
  SpectralTables t;
  t.period_nm = grating.period_nm();
  t.sigma_nm = grating.coherence_nm;
  t.R0 = std::pow((grating.ior - 1.0) / (grating.ior + 1.0), 2);
  double sum = 0.0;
  for (double h : grating.height_nm) sum += h;
  t.mean_nm = sum / static_cast<double>(grating.height_nm.size());
  double spread = 0.0;
  for (double h : grating.height_nm) spread = std::max(spread, std::abs(h - t.mean_nm));
  t.hs_nm = spread > 0.0 ? spread : 1.0;  // a flat patch: any unit works, every H_n>0 is 0
  t.x_max = ((2.0 * std::numbers::pi) / range.lambda_min_nm) * range.w_max * spread;
  t.N = range.terms > 0 ? range.terms : taylor_term_count(t.x_max, range.tolerance);
  t.stored_terms = t.N;
  t.r = window_radius(t.period_nm, t.sigma_nm, range.tolerance);
  // |u|, |v| <= 2, so k u reaches bin 2 T / lambda_min; the window adds r bins. Beyond the Nyquist
  // bin the sampled height field carries no information.
  const int reach = static_cast<int>(std::ceil(2.0 * t.period_nm / range.lambda_min_nm)) + t.r;
  t.J = std::min(reach, M / 2 - 1);

  assets::RealFft2d fft(M, M);
  std::vector<double> normalised(grating.height_nm.size()), power(grating.height_nm.size(), 1.0);
  for (size_t i = 0; i < normalised.size(); ++i) normalised[i] = (grating.height_nm[i] - t.mean_nm) / t.hs_nm;
  const size_t per_term = static_cast<size_t>(t.J + 1) * (2 * t.J + 1);
  t.coefficients.resize(per_term * t.N);
  const double scale = 1.0 / (static_cast<double>(M) * M);
  for (int n = 0; n < t.N; ++n) {
    const auto spectrum = fft.forward(power);
    for (int jy = 0; jy <= t.J; ++jy)
      for (int jx = -t.J; jx <= t.J; ++jx) {
        const auto entry = kernels::f64::diffraction_table_entry(n, jx, jy, t.J, t.stored_terms);
        t.coefficients[entry.index] = scale * stam_bin(spectrum, M, jx, jy);
      }
    for (size_t i = 0; i < power.size(); ++i) power[i] *= normalised[i];
  }
  return t;
}

}  // namespace facet::diffraction
