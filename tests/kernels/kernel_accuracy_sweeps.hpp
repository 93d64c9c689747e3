// Dense sweeps of the double kernels against the 50-digit references of support/multiprecision_reference.hpp,
// shared by the test (tests/kernels/kernel_accuracy_test.cpp, which checks every bound) and the report
// (bench/kernel_accuracy.cpp, which writes the table of docs/kernel_accuracy.md).
//
// Each sweep returns one row per (kernel, quantity): the worst error over its points, where it occurs, and
// the bound the test enforces there. Points are log-spaced over each parameter's whole range and dense
// around every branch boundary of the kernel; random parameters come from fixed seeds. `density` multiplies
// the number of points: 1 in the test (it runs under the sanitizers), 4 for the report.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "diffraction/chebyshev_transform.hpp"
#include "diffraction/spectral_tables.hpp"
#include "kernels/cross_section_exact.hpp"
#include "kernels/shared.hpp"
#include "support/multiprecision_reference.hpp"
#include "visible_slope_cases.hpp"

namespace facet::test::accuracy {

// Bounds are target + allowance, the allowance being the input floor where the answer is ill-conditioned.
struct Row {
  std::string kernel, quantity, measure;
  int points = 0;
  double worst = 0;              // largest error
  std::string where;             // where it occurs
  int conditioned = 0;           // points whose allowance is below target/10 (well-conditioned answers)
  double worst_conditioned = 0;  // largest error over those: the kernel's own accuracy
  std::string conditioned_where;
  double excess = 0;  // largest error / bound over the sweep: the test requires <= 1
  std::string bound;  // the bound, in words
};

// Tracks one row's worst errors.
class Worst {
 public:
  Worst(std::string kernel, std::string quantity, std::string measure, std::string bound) {
    row_.kernel = std::move(kernel);
    row_.quantity = std::move(quantity);
    row_.measure = std::move(measure);
    row_.bound = std::move(bound);
  }
  void add(double error, double target, double allowance, const std::string& where) {
    ++row_.points;
    if (worse(error, row_.worst)) {
      row_.worst = error;
      row_.where = where;
    }
    if (allowance < target / 10) {
      ++row_.conditioned;
      if (worse(error, row_.worst_conditioned)) {
        row_.worst_conditioned = error;
        row_.conditioned_where = where;
      }
    }
    const double excess = error / (target + allowance);
    if (worse(excess, row_.excess)) row_.excess = excess;
  }
  const Row& row() const { return row_; }

 private:
  // NaN is worse than anything and stays.
  static bool worse(double a, double b) { return !std::isnan(b) && !(a <= b); }
  Row row_;
};

inline std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
  return buffer;
}

// v from lo to hi (same sign), n points, log-spaced.
inline std::vector<double> log_spaced(double lo, double hi, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = lo * std::pow(hi / lo, n == 1 ? 0.0 : double(i) / (n - 1));
  return v;
}

inline double rel(double value, const mp::Real& reference) {
  return static_cast<double>(abs((mp::Real(value) - reference) / reference));
}

// --- Special functions (special_functions.glsl), relative errors. ---

inline std::vector<Row> special_function_rows(int density) {
  using namespace kernels::f64;
  const std::string tight = "8 eps = 1.8e-15";
  Worst erfcx("sf_erfcx", "erfcx(x)", "relative", tight), erfc("sf_erfc", "erfc(x)", "relative", tight),
      erf("sf_erf", "erf(x)", "relative", tight), ratio("sf_phi_over_Phi", "phi(t)/Phi(t)", "relative", tight),
      log_cdf("sf_log_normal_cdf", "log Phi(t)", "relative", "16 eps = 3.6e-15"),
      quantile("sf_normal_quantile_upper_log", "x with log Q(x) = log q", "error of x / max(1, x)", tight);
  std::vector<double> xs = log_spaced(1e-6, 1e6, 160 * density), negative = log_spaced(-26.5, -1e-6, 100 * density);
  xs.insert(xs.end(), negative.begin(), negative.end());
  for (int i = 0; i < 25 * density; ++i) xs.push_back(1.9 + 0.2 * i / (25 * density));  // u = (x-2)/(x+2) = 0 at 2
  for (double x : xs) {
    const mp::Real X = x;
    const mp::Real ex = mp::erfcx(X);
    erfcx.add(rel(sf_erfcx(x), ex), 1.8e-15, 0, format("x = %.6g", x));
    if (x < 26.5) {  // erfc(26.5) = 1e-307: below it erfc is subnormal
      const mp::Real ec = X >= 0 ? exp(-X * X) * ex : 2 - exp(-X * X) * mp::erfcx(-X);
      erfc.add(rel(sf_erfc(x), ec), 1.8e-15, 0, format("x = %.6g", x));
      erf.add(rel(sf_erf(x), mp::erf(X)), 1.8e-15, 0, format("x = %.6g", x));
    }
  }
  for (double x : {-0.5, -0.4999999999, 0.4999999999, 0.5})  // erf's series / erfc switch
    erf.add(rel(sf_erf(x), mp::erf(mp::Real(x))), 1.8e-15, 0, format("x = %.10g", x));
  // Up to t = 37.5, where phi(t) is still a normal double.
  std::vector<double> ts = log_spaced(-1e4, -1e-4, 100 * density), positive = log_spaced(1e-4, 37.5, 60 * density);
  ts.insert(ts.end(), positive.begin(), positive.end());
  for (double t : ts) {
    ratio.add(rel(sf_phi_over_Phi(t), mp::normal_pdf(t) / mp::normal_tail(-mp::Real(t))), 1.8e-15, 0,
              format("t = %.6g", t));
    log_cdf.add(rel(sf_log_normal_cdf(t), mp::log_normal_cdf(t)), 3.6e-15, 0, format("t = %.6g", t));
  }
  for (double log_q : log_spaced(-std::numbers::ln2, -1e6, 80 * density)) {
    // Residual of log Q at the returned x, turned into an error in x by d log Q/dx = -1/R(x), R = Q/phi.
    const double x = sf_normal_quantile_upper_log(log_q);
    const mp::Real Q = mp::normal_tail(mp::Real(x));
    const mp::Real R = Q / mp::normal_pdf(x);
    const double dx = static_cast<double>(abs((log(Q) - log_q) * R));
    quantile.add(dx / std::max(1.0, x), 1.8e-15, 0, format("log q = %.6g", log_q));
  }
  return {erfcx.row(), erfc.row(), erf.row(), ratio.row(), log_cdf.row(), quantile.row()};
}

// --- Smith masking of a non-centred Gaussian slope law (gaussian_masking.glsl), as a function of t. ---

// Lambda ~ phi(t)/t^2 is taken as exp(log m_1(-t) - log t), whose rounding (eps |log m_1| ~ eps t^2/2) is
// also the change of Lambda under a relative change eps of t: the bound is 1e-13 + eps t^2.
inline std::vector<Row> masking_rows(int density) {
  using namespace kernels::f64;
  Worst lambda("gaussian_smith_lambda_of_t", "Lambda(t)", "relative", "1e-13 + eps t^2"),
      g1("gaussian_smith_g1 (via Lambda)", "G1 = 1/(1 + Lambda)", "relative", "1e-13");
  std::vector<double> ts = log_spaced(1e-4, 37, 150 * density);
  for (int i = 0; i < 25 * density; ++i) ts.push_back(1.1 + 0.3 * i / (25 * density));  // CF threshold at -t
  for (double t : ts) {
    const mp::Real L = mp::smith_lambda(t);
    const double l = gaussian_smith_lambda_of_t(t);
    lambda.add(rel(l, L), 1e-13, 0x1p-53 * t * t, format("t = %.6g", t));
    g1.add(rel(1 / (1 + l), 1 / (1 + L)), 1e-13, 0, format("t = %.6g", t));
  }
  return {lambda.row(), g1.row()};
}

// --- Visible heights (gaussian_masking.glsl) for heights N(0, 1), so the kernel's own rounding is measured. ---

// Heights with CDF C = Phi seen under Smith's height-correlated masking have density (1 + Lambda) C^Lambda c
// (docs/masking.md), whose integral over (-inf, z] is C^(1 + Lambda) (checked against quadrature of the density in
// ReferencesAgreeWithIndependentMethods); C comes from the erfc integral.

// CDF = exp(x), x = (1 + Lambda) log Phi(z): a rounding of Lambda moves x by eps |x|, and log Phi's own error
// (bounded by 16 eps = 3.6e-15 above) by 3.6e-15 |x|, which is the allowance (relative); the density likewise with
// x = Lambda log Phi - z^2/2. sample(u) returns z with
// CDF(z) = u; its error is the residual of log CDF at z divided by d log CDF/dz = (1 + Lambda) phi/Phi, and its
// allowance the move of z under a rounding of log C = log u/(1 + Lambda), eps |log C| Phi/phi.
inline std::vector<Row> visible_height_rows(int density) {
  using namespace kernels::f64;
  constexpr double kLogCdfAllowance = 0x1p-53 + 3.6e-15;
  Worst cdf("visible_height_cdf", "C^(1 + Lambda)", "relative", "1e-13 + (eps + 3.6e-15) abs(log CDF)"),
      pdf("visible_height_pdf", "(1 + Lambda) C^Lambda c", "relative", "1e-13 + (eps + 3.6e-15) abs(log pdf)"),
      sample("visible_height_sample", "z with CDF(z) = u", "error of z / max(1, abs(z))",
             "1e-13 + eps abs(log C) Phi/phi");
  // z from the CDF's underflow to 1 - 1e-30; log Phi(z) is shared by every Lambda.
  std::vector<std::pair<double, mp::Real>> log_Phi;
  for (int i = 0; i < 40 * density; ++i) {
    const double z = -37 + 49.0 * i / (40 * density - 1);
    log_Phi.emplace_back(z, mp::log_normal_cdf(z));
  }
  for (double lambda : {0.0, 1e-6, 0.7, 25.0, 1e3, 1e6, 1e8}) {
    const mp::Real L = lambda;
    char at[64];
    for (const auto& [z, log_C] : log_Phi) {
      const mp::Real log_cdf = (1 + L) * log_C;  // CDF = C^(1 + Lambda)
      if (log_cdf < -700) continue;              // the kernel's CDF underflows there
      std::snprintf(at, sizeof at, "z = %.4g, Lambda = %.3g", z, lambda);
      cdf.add(rel(visible_height_cdf(z, 0, 1, lambda), exp(log_cdf)), 1e-13, kLogCdfAllowance * double(abs(log_cdf)),
              at);
      const mp::Real log_pdf = L * log_C - mp::Real(z) * z / 2;
      const mp::Real ref_pdf = (1 + L) * exp(log_pdf) / mp::kSqrt2Pi;
      pdf.add(rel(visible_height_pdf(z, 0, 1, lambda), ref_pdf), 1e-13, kLogCdfAllowance * double(abs(log_pdf)), at);
    }
    std::vector<double> us = log_spaced(1e-300, 0.5, 30 * density), upper = log_spaced(0.5, 1e-9, 15 * density);
    for (double q : upper) us.push_back(1 - q);
    for (double u : us) {
      const double z = visible_height_sample(u, 0, 1, lambda);
      const mp::Real Z = z;
      const mp::Real log_Phi = mp::log_normal_cdf(Z);
      const mp::Real rho = mp::normal_pdf(Z) / exp(log_Phi);
      const double dz = double(abs(((1 + L) * log_Phi - log(mp::Real(u))) / ((1 + L) * rho)));
      const double allowance = double(0x1p-53 * abs(log(mp::Real(u)) / (1 + L)) / rho);
      const double scale = std::max(1.0, std::abs(z));
      std::snprintf(at, sizeof at, "u = %.4g, Lambda = %.3g", u, lambda);
      sample.add(dz / scale, 1e-13, allowance / scale, at);
    }
  }
  return {cdf.row(), pdf.row(), sample.row()};
}

// --- Visible slopes (visible_slope.glsl). ---

// Error measures of visible_slope_cases.hpp: |d log N|, mean / sqrt(tr Sigma_s), covariance / tr Sigma_s;
// bound 1e-13 + 4 x the input floor (the change of the exact answer under a relative change eps of the
// inputs, which the kernel cannot beat since it rounds cot theta and s_mean . omega itself).
struct SlopeSweep {
  Worst log_N{"visible_slope", "log N", "error of log N (= relative error of N)", "1e-13 + 4 x input floor"};
  Worst mean{"visible_slope", "mean", "max error of mean / sqrt(tr Sigma_s)", "1e-13 + 4 x input floor"};
  Worst cov{"visible_slope", "covariance", "max error of cov / tr Sigma_s", "1e-13 + 4 x input floor"};

  void add(const SlopeCase& k) {
    const mp::VisibleSlope r = mp::visible_slope(k.mean_x, k.mean_y, k.var_x, k.var_y, k.c_xy, k.theta, k.phi);
    const auto d = kernels::f64::visible_slope({k.mean_x, k.mean_y}, {k.var_x, k.var_y, k.c_xy}, k.theta, k.phi);
    const SlopeMoments rd{double(r.log_N), double(r.mean_x), double(r.mean_y),
                          double(r.var_x), double(r.var_y),  double(r.c_xy)};
    const Errors floor = input_floor(k, rd, 0x1p-53);
    const mp::Real tr = r.var_x + r.var_y;
    auto d_of = [](double v, const mp::Real& ref) { return static_cast<double>(abs(mp::Real(v) - ref)); };
    const double e_log_N = d_of(d.log_N, r.log_N);
    const double e_mean = std::max(d_of(d.mean.x, r.mean_x), d_of(d.mean.y, r.mean_y)) / static_cast<double>(sqrt(tr));
    const double e_cov =
        std::max({d_of(d.cov.x, r.var_x), d_of(d.cov.y, r.var_y), d_of(d.cov.z, r.c_xy)}) / static_cast<double>(tr);
    const double t = kernels::f64::slope_view_frame({k.mean_x, k.mean_y}, {k.var_x, k.var_y, k.c_xy}, k.theta, k.phi).t;
    char where[200];
    std::snprintf(where, sizeof where, "t = %.4g (mean %.3g %.3g, cov %.3g %.3g %.3g, theta %.4g, phi %.3g)", t,
                  k.mean_x, k.mean_y, k.var_x, k.var_y, k.c_xy, k.theta, k.phi);
    log_N.add(e_log_N, 1e-13, 4 * floor.log_N, where);
    mean.add(e_mean, 1e-13, 4 * floor.mean, where);
    cov.add(e_cov, 1e-13, 4 * floor.cov, where);
  }
  std::vector<Row> rows(const std::string& sweep) const {
    std::vector<Row> out = {log_N.row(), mean.row(), cov.row()};
    for (Row& r : out) r.kernel += " (" + sweep + ")";
    return out;
  }
};

// Beckmann cross-section sigma(w) = int D(m) max(0, m.w) dm (ndf_beckmann.glsl), which in slope space is
// int p(s) max(0, w_z - s.w_xy) ds with p = N(0, alpha^2/2 I): the N of the visible slope reference for a centred law
// (eq. 16). w = (sin theta, 0, cos theta) over theta in (0, pi), alpha from 1e-3 to 10, where sigma is a normal
// double; error of log sigma with the visible slopes' input floor.
inline std::vector<Row> beckmann_sigma_rows(int density) {
  Worst sigma("ndf_beckmann_sigma", "sigma(w)", "relative (error of log sigma)", "1e-13 + 4 x input floor");
  for (double alpha : log_spaced(1e-3, 10, 8 * density))
    for (int i = 1; i < 16 * density; ++i) {
      const double theta = std::numbers::pi * i / (16 * density);
      const SlopeCase k{0, 0, alpha * alpha / 2, alpha * alpha / 2, 0, theta, 0};
      const mp::VisibleSlope r = mp::visible_slope(k.mean_x, k.mean_y, k.var_x, k.var_y, k.c_xy, k.theta, k.phi);
      if (r.log_N < -708) continue;  // sigma is below the smallest normal double
      const double s = kernels::f64::ndf_beckmann_sigma({std::sin(theta), 0, std::cos(theta)}, glm::dvec2(alpha));
      const SlopeMoments rd{double(r.log_N), 0, 0, k.var_x, k.var_y, 0};
      char at[64];
      std::snprintf(at, sizeof at, "alpha = %.3g, theta = %.4g", alpha, theta);
      sigma.add(static_cast<double>(abs(log(mp::Real(s)) - r.log_N)), 1e-13, 4 * input_floor(k, rd, 0x1p-53).log_N, at);
    }
  return {sigma.row()};
}

// --- Cross-sections sigma(u) of GGX, Kagiwada-Kalaba and the spherical Gaussian (docs/cross_sections.md) against
// mp::isotropic_sigma, the integral over directions. ndf_sigma_u takes u itself, which the reference uses exactly:
// no input floor. ---

// u over [-1, 1]: uniform, and log-spaced towards the kernels' branch boundary u = 0 (both sides) and towards +-1.
// A reference costs 5-20 ms (mp::isotropic_sigma), hence few points at density 1.
inline std::vector<double> cross_section_us(int density) {
  std::vector<double> us;
  for (int i = 0; i <= 4 * density; ++i) us.push_back(-1 + 2.0 * i / (4 * density));
  for (double d : log_spaced(1e-8, 1e-2, density))
    for (double u : {-d, d, -1 + d, 1 - d}) us.push_back(u);
  return us;
}

// Relative error; where sigma = 0 exactly (GGX at u = -1) the kernel must return 0.
inline double rel_or_zero(double value, const mp::Real& reference) {
  if (reference == 0) return value == 0 ? 0 : std::numeric_limits<double>::infinity();
  return rel(value, reference);
}

inline std::string at_u(const char* name, double param, double u) {
  char at[80];
  std::snprintf(at, sizeof at, "%s = %.9g, u = %.6g", name, param, u);
  return at;
}

// GGX, alpha from 1e-3 to 1e3; the kernel's branch is u >= 0 / u < 0.
inline std::vector<Row> ggx_sigma_rows(int density) {
  Worst sigma("ndf_ggx_sigma", "sigma(u)", "relative", "8 eps = 1.8e-15");
  const std::vector<double> us = cross_section_us(density);
  for (double alpha : log_spaced(1e-3, 1e3, 2 * density + 1))
    for (double u : us) {
      const double d = kernels::f64::ndf_sigma_u(NDF_GGX, u, alpha);
      sigma.add(rel_or_zero(d, mp::ggx_sigma(alpha, u)), 1.8e-15, 0, at_u("alpha", alpha, u));
    }
  return {sigma.row()};
}

// Kagiwada-Kalaba over the kernel's clamped range b in [1e-6, 1 - 1e-6], log-spaced towards both ends. The bound is
// looser where R^2 = 1 - b^2 (1 - u^2) cancels (b -> 1, u -> 0: R ~ sqrt(2 (1 - b))), which the kernel computes as
// written: R is then off by ~eps/(2 R), and sigma (through b s^2/(1 + R)) by as much relative; allowance 2 eps/R.
inline std::vector<Row> kk_sigma_rows(int density) {
  Worst sigma("ndf_kk_sigma", "sigma(u)", "relative", "8 eps + 2 eps/sqrt(2 (1 - b))");
  std::vector<double> bs = log_spaced(1e-6, 0.5, density);
  for (double q : log_spaced(1e-6, 0.3, density)) bs.push_back(1 - q);
  const std::vector<double> us = cross_section_us(density);
  for (double b : bs)
    for (double u : us) {
      const double d = kernels::f64::ndf_sigma_u(NDF_KK, u, b);
      sigma.add(rel(d, mp::kk_sigma(b, u)), 1.8e-15, 0x1p-52 / std::sqrt(2 * (1 - b)), at_u("b", b, u));
    }
  return {sigma.row()};
}

// Spherical Gaussian, alpha from 1e-3 to 1e3 and across the fast kernel's switch kappa = 200 (alpha = 0.1): the
// exact CPU quadrature sg_cross_section_exact (relative, with an absolute allowance 1e-16 where sigma is tiny: its
// stated accuracy is absolute) and the fast kernel ndf_sg_sigma_u (absolute; docs/cross_sections.md states 1.76e-5
// on its own grid, this sweep finds 2e-5 at the switch). Points where sigma is below the smallest normal double are
// left out.
inline std::vector<Row> sg_sigma_rows(int density) {
  Worst exact("sg_cross_section_exact", "sigma(u)", "relative", "1e-13 + 1e-16/sigma"),
      fast("ndf_sg_sigma (Legendre / cumulant)", "sigma(u)", "absolute", "2.5e-5");
  std::vector<double> alphas = log_spaced(1e-3, 1e3, 2 * density);
  const double switch_alpha = std::sqrt(2 / 200.0);
  for (double f : {1 - 1e-9, 1 + 1e-9}) alphas.push_back(switch_alpha * f);
  const std::vector<double> us = cross_section_us(density);
  for (double alpha : alphas)
    for (double u : us) {
      const mp::Real ref = mp::sg_sigma(alpha, u);
      if (ref < 1e-300) continue;
      const std::string at = at_u("alpha", alpha, u);
      exact.add(rel(kernels::sg_cross_section_exact(alpha, u), ref), 1e-13, 1e-16 / double(ref), at);
      fast.add(double(abs(mp::Real(kernels::f64::ndf_sigma_u(NDF_SG, u, alpha)) - ref)), 2.5e-5, 0, at);
    }
  return {exact.row(), fast.row()};
}

// --- Diffraction: the Taylor term count (renderer/diffraction/spectral_tables.cpp). ---

// taylor_term_count(x_max, tol) is the smallest N with x_max^N/N! <= tol, the Lagrange bound of the truncated series
// of e^{ix}. Checked against the definition of the error it bounds, |e^{ix} - sum_{n<N} (ix)^n/n!|, in 50 digits
// (cos, sin and the partial sum, whose cancellation costs log10 e^x < 10 of the 50 digits), at x = x_max j/8,
// j = 1..8 (the series serves every |x| <= x_max). x_max over [1e-3, 24], tolerances over [1e-15, 0.1]; pairs that
// would need more than the tables' cap of Taylor terms throw and are left out.
inline std::vector<Row> taylor_rows(int density) {
  const std::string quantity = "abs(e^{ix} - sum_{n<N} (ix)^n/n!), abs(x) <= x_max";
  Worst error("taylor_term_count", quantity, "error / tolerance", "1"),
      lagrange("taylor_term_count", quantity, "error / (x_max^N/N!)", "1 (the Lagrange bound)");
  for (double tol : log_spaced(1e-15, 0.1, 8 * density))
    for (double x_max : log_spaced(1e-3, 24, 40 * density)) {
      int N = 0;
      try {
        N = diffraction::taylor_term_count(x_max, tol);
      } catch (const Error&) {
        continue;
      }
      mp::Real bound = 1;
      for (int n = 1; n <= N; ++n) bound *= mp::Real(x_max) / n;
      char at[80];
      std::snprintf(at, sizeof at, "x_max = %.4g, tol = %.3g, N = %d", x_max, tol, N);
      for (int j = 1; j <= 8; ++j) {
        const mp::Real x = mp::Real(x_max) * j / 8;
        mp::Real sum[2] = {0, 0}, term = 1;  // real, imaginary parts; term = x^n/n!
        for (int n = 0; n < N; ++n) {
          sum[n % 2] += n % 4 < 2 ? term : -term;  // i^n = 1, i, -1, -i
          term *= x / (n + 1);
        }
        const mp::Real e = hypot(cos(x) - sum[0], sin(x) - sum[1]);
        error.add(static_cast<double>(e / tol), 1, 0, at);
        lagrange.add(static_cast<double>(e / bound), 1, 0, at);
      }
    }
  return {error.row(), lagrange.row()};
}

// --- Diffraction: the exact transform's Chebyshev interpolation (renderer/diffraction/chebyshev_transform.cpp). ---

// ChebyshevTransform interpolates, in x over [-x_max, 0], every band bin of p_j(x) = (1/M^2) sum_s exp(i x h(s))
// exp(+i 2 pi j.s/M), h = (height - mean)/h_s; here p_j is that sum in 50 digits. A tall sinusoid on a 16 x 16 patch
// (x_max = 10.5: three pieces), x uniform over the range and either side of every piece boundary. Error: the
// largest |interpolant - p_j| over the band; bound: the interpolant's proven remainder (error_bound()) + 1e-13 for the
// rounding of its node values (tests/diffraction/chebyshev_transform_test.cpp).
inline std::vector<Row> chebyshev_transform_rows(int density) {
  const auto grating = diffraction::grating_from_json(
      nlohmann::json::parse(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":300,"size_um":4,"samples":16})"),
      "kernel_accuracy");
  const auto tables =
      diffraction::build_spectral_tables(grating, {.lambda_min_nm = 360, .tolerance = 1e-3, .terms = 1});
  const diffraction::ChebyshevTransform cheb(grating, tables);
  const double bound = cheb.error_bound() + 1e-13;
  Worst error("ChebyshevTransform", "band bins p_j(x), x in [-x_max, 0]", "max over bins of abs error",
              format("error_bound() + 1e-13 = %.2g", bound));
  const int M = grating.samples, J = tables.J;
  std::vector<mp::Real> h(M * M), c(M), s(M);  // normalised heights; cos, sin of 2 pi k/M
  for (int i = 0; i < M * M; ++i) h[i] = (mp::Real(grating.height_nm[i]) - tables.mean_nm) / tables.hs_nm;
  for (int k = 0; k < M; ++k) {
    c[k] = cos(2 * mp::kPi * k / M);
    s[k] = sin(2 * mp::kPi * k / M);
  }
  const double x_max = cheb.x_max();
  // A reference costs ~30 ms an x: 3 uniform points in the test, 300 in the report; every piece boundary +- 1e-9.
  const int n = density > 1 ? 75 * density : 3;
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) xs.push_back(-x_max * i / (n - 1));
  const int pieces = static_cast<int>(std::ceil(x_max / diffraction::ChebyshevTransform::kMaxPiece));
  for (int k = 1; k < pieces; ++k)
    for (double d : {-1e-9, 1e-9}) xs.push_back(-x_max * k / pieces + d);
  for (double x : xs) {
    std::vector<mp::Real> re(M * M), im(M * M);
    for (int i = 0; i < M * M; ++i) {
      re[i] = cos(x * h[i]);
      im[i] = sin(x * h[i]);
    }
    const diffraction::ChebyshevTransform::AtX at = cheb.at(x);
    double worst = 0;
    for (int jy = -J; jy <= J; ++jy)
      for (int jx = -J; jx <= J; ++jx) {
        mp::Real sum_re = 0, sum_im = 0;
        for (int y = 0; y < M; ++y)
          for (int sx = 0; sx < M; ++sx) {
            const int k = ((jx * sx + jy * y) % M + M) % M;  // exp(+i 2 pi j.s/M) = c[k] + i s[k]
            const int i = y * M + sx;
            sum_re += re[i] * c[k] - im[i] * s[k];
            sum_im += re[i] * s[k] + im[i] * c[k];
          }
        const std::complex<double> v = at.bin(jx, jy);
        worst = std::max(worst, static_cast<double>(hypot(v.real() - sum_re / (M * M), v.imag() - sum_im / (M * M))));
      }
    error.add(worst, bound, 0, format("x = %.10g", x));
  }
  return {error.row()};
}

// The case with horizon variable t (before the inputs are rounded), given the other parameters: the mean
// is placed along omega's azimuth so that (cot theta - mean_o)/sigma_o = t, mean_perp as given.
inline SlopeCase case_at(double t, double var_x, double var_y, double c_xy, double theta, double phi,
                         double mean_perp) {
  const double c = std::cos(phi), s = std::sin(phi);
  const double sigma_o = std::sqrt(var_x * c * c + var_y * s * s + 2 * c_xy * c * s);
  const double mean_o = std::cos(theta) / std::sin(theta) - t * sigma_o;
  return {mean_o * c - mean_perp * s, mean_o * s + mean_perp * c, var_x, var_y, c_xy, theta, phi};
}

// The sweep of issue 21: theta = 45 deg, isotropic and anisotropic laws (var_y 1 to 0.05, c_xy up to 0.1),
// the mean moved back so that t runs from -3 to -1000.
// The band -40 <= t <= -16 where the issue reported 4e-8 is also reported on its own.
inline std::vector<Row> visible_slope_issue_rows(int density) {
  SlopeSweep sweep, band;
  int law = 0;
  for (double var_y : {1.0, 0.3, 0.05})
    for (double c_xy : {0.0, 0.1}) {
      const double phi = 0.37 * law++;
      for (double t : log_spaced(-3, -1000, 40 * density)) {
        const SlopeCase k = case_at(t, 1.0, var_y, c_xy, std::numbers::pi / 4, phi, 0.2);
        sweep.add(k);
        if (t <= -16 && t >= -40) band.add(k);
      }
      for (double t : log_spaced(-16, -40, 5 * density))
        band.add(case_at(t, 1.0, var_y, c_xy, std::numbers::pi / 4, phi, 0.2));
    }
  std::vector<Row> rows = sweep.rows("issue 21: theta = 45 deg, t from -3 to -1000");
  for (const Row& r : band.rows("issue 21, band -40 <= t <= -16")) rows.push_back(r);
  return rows;
}

// The whole domain: t log-spaced over [-1e4, -1e-4] and [1e-4, 1e6], dense across the branch boundaries
// t = -T0 (continued fraction) and 0, each with random variances (1e-4..1e2), correlation (|rho| < 0.99),
// theta (0.02..1.55), phi and mean_perp.
inline std::vector<Row> visible_slope_domain_rows(int density) {
  const int points = 400 * density;
  SlopeSweep sweep;
  std::vector<double> ts = log_spaced(-1e4, -1e-4, points / 2), positive = log_spaced(1e-4, 1e6, points / 4);
  ts.insert(ts.end(), positive.begin(), positive.end());
  for (int i = 0; i < points / 8; ++i) ts.push_back(-1 - 3.0 * i / (points / 8));    // -1 .. -4
  for (int i = 0; i < points / 8; ++i) ts.push_back(-0.1 + 0.2 * i / (points / 8));  // around 0
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> uni(0, 1);
  for (double t : ts) {
    const double var_x = std::pow(10.0, -4 + 6 * uni(rng)), var_y = std::pow(10.0, -4 + 6 * uni(rng));
    const double rho = 1.98 * uni(rng) - 0.99;
    const double theta = 0.02 + 1.53 * uni(rng), phi = 2 * std::numbers::pi * uni(rng);
    sweep.add(case_at(t, var_x, var_y, rho * std::sqrt(var_x * var_y), theta, phi,
                      (2 * uni(rng) - 1) * std::sqrt(var_x + var_y)));
  }
  return sweep.rows("whole domain");
}

// Extreme inputs: variances 1e-10..1e4, correlations +-(1 - 1e-6), near-grazing and near-normal views.
inline std::vector<Row> visible_slope_extreme_rows() {
  SlopeSweep sweep;
  for (double var : {1e-10, 1e-3, 1e4})
    for (double rho : {-(1 - 1e-6), 0.0, 1 - 1e-6})
      for (double theta : {1e-6, 0.3, 1.5, std::numbers::pi / 2 - 1e-7})
        for (double t : {-300.0, -20.0, -2.0, -0.5, 0.5, 5.0})
          sweep.add(case_at(t, var, 0.3 * var, rho * std::sqrt(0.3) * var, theta, 0.8, 0.1 * std::sqrt(var)));
  return sweep.rows("extreme inputs");
}

}  // namespace facet::test::accuracy
