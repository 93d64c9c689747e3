#include "report/kernel_stability.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/erf.hpp>

#include "eval_cross_section.spv.h"
#include "gpu/batch_eval.hpp"
#include "kernels/cross_section_exact.hpp"
#include "kernels/shared.hpp"

namespace facet::report {

namespace {

using Real = long double;
namespace f32 = kernels::f32;
namespace f64 = kernels::f64;

// Relative error of `got` against `want`; NaN and inf count as error 1e300 so they always show.
double relative_error(double got, Real want) {
  if (!std::isfinite(got)) return 1e300;
  return static_cast<double>(std::fabs(static_cast<Real>(got) - want) / std::fabs(want));
}

// Evenly spaced points of [lo, hi], both ends included.
std::vector<double> linspace(double lo, double hi, int count) {
  std::vector<double> points;
  for (int i = 0; i < count; ++i) points.push_back(lo + (hi - lo) * i / (count - 1));
  return points;
}

StabilityRow describe(std::string kernel, std::string domain, std::string reference, std::string measure) {
  StabilityRow row;
  row.kernel = std::move(kernel);
  row.domain = std::move(domain);
  row.reference = std::move(reference);
  row.measure = std::move(measure);
  return row;
}

// Worst relative error of the f64 and f32 twins of a scalar function over their own domains.
StabilityRow scalar_row(StabilityRow row, const std::vector<double>& domain64, const std::vector<double>& domain32,
                        const std::function<double(double)>& twin64, const std::function<float(float)>& twin32,
                        const std::function<Real(Real)>& reference) {
  double worst64 = 0.0, worst32 = 0.0;
  for (double x : domain64) worst64 = std::max(worst64, relative_error(twin64(x), reference(x)));
  for (double x : domain32) {
    const float xf = static_cast<float>(x);  // the reference at the float input: only the kernel's error counts
    worst32 = std::max(worst32, relative_error(twin32(xf), reference(xf)));
  }
  row.f64 = worst64;
  row.f32 = worst32;
  return row;
}

// erfcx(x) = exp(x^2) erfc(x); long double keeps exp(x^2) finite to x = 106.
Real erfcx_reference(Real x) { return std::exp(x * x) * boost::math::erfc(x); }

// log Phi(t) with Phi(t) = erfc(-t/sqrt2)/2, finite in long double down to t = -150; for t > 0 as
// log1p(-Q(t)), since log(1 - Q) would lose log Phi's relative accuracy where it is tiny.
Real log_normal_cdf_reference(Real t) {
  if (t > 0) return std::log1p(-0.5L * boost::math::erfc(t / std::numbers::sqrt2_v<Real>));
  return std::log(0.5L * boost::math::erfc(-t / std::numbers::sqrt2_v<Real>));
}

Real normal_pdf(Real t) { return std::exp(-0.5L * t * t) / std::sqrt(2.0L * std::numbers::pi_v<Real>); }

// Lambda(t) = E[max(0, -z)]/t for z ~ N(t, 1) = phi(t)/t * int_0^inf x exp(-x t - x^2/2) dx, by
// exp-sinh quadrature: no cancellation between phi(t) and t Q(t).
Real smith_lambda_reference(Real t) {
  static boost::math::quadrature::exp_sinh<Real> integrator;  // Boost 1.74's [0, inf) integrate() is not const
  const auto integrand = [t](Real x) { return x * std::exp(-x * t - 0.5L * x * x); };
  const Real integral = integrator.integrate(integrand);
  return normal_pdf(t) / t * integral;
}

// sigma(u) of one NDF over its parameter range and u in [-1, 1]: float twin and GPU against the
// double closed forms (the spherical Gaussian: quadrature), errors relative to max(1, sigma).
StabilityRow cross_section_row(vk::Context& context, int ndf, const char* name) {
  std::vector<gpu::EvalRecord> inputs;
  std::vector<double> exact;
  double worst64 = 0.0, worst32 = 0.0, worst_gpu = 0.0;
  for (int i = 0; i <= 24; ++i) {
    const double param = ndf == 2 ? std::clamp(i / 24.0, 1e-6, 1.0 - 1e-6) : std::pow(10.0, -3.0 + 6.0 * i / 24.0);
    for (double u : linspace(-1.0, 1.0, 41)) {
      const float pf = static_cast<float>(param), uf = static_cast<float>(u);
      const double want = kernels::cross_section(ndf, pf, uf, /*exact=*/true);
      const double scale = std::max(1.0, std::fabs(want));
      worst64 = std::max(worst64, std::fabs(f64::ndf_sigma_u(ndf, uf, pf) - want) / scale);
      const float got32 = f32::ndf_sigma_u(ndf, uf, pf);
      worst32 = std::max(worst32, std::isfinite(got32) ? std::fabs(got32 - want) / scale : 1e300);
      inputs.push_back({glm::vec4(static_cast<float>(ndf), pf, uf, 0.0f), glm::vec4(0.0f)});
      exact.push_back(want);
    }
  }
  const auto outputs = gpu::run_batch_eval(context, "eval_cross_section", eval_cross_section_spv, inputs);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const double got = outputs[i].a.x;
    worst_gpu = std::max(worst_gpu,
                         std::isfinite(got) ? std::fabs(got - exact[i]) / std::max(1.0, std::fabs(exact[i])) : 1e300);
  }
  StabilityRow row =
      describe(std::string("ndf_sigma_u (") + name + ")",
               ndf == 2 ? "b in [1e-6, 1-1e-6], u in [-1, 1]" : "alpha in [1e-3, 1e3], u in [-1, 1]",
               ndf == 3 ? "adaptive quadrature in double" : "closed form in double (the f64 twin itself)",
               "|error| / max(1, sigma)");
  row.f32 = worst32;
  row.gpu = worst_gpu;
  if (ndf == 3) row.f64 = worst64;  // elsewhere the f64 twin is the reference, so its error is 0 by construction
  return row;
}

}  // namespace

std::vector<StabilityRow> kernel_stability(vk::Context& context) {
  std::vector<StabilityRow> rows;
  rows.push_back(scalar_row(
      describe("sf_erfcx", "x in [-26, 100] (f32: [-9, 100])", "Boost erfc x exp(x^2), long double", "relative"),
      linspace(-26.0, 100.0, 5041), linspace(-9.0, 100.0, 4361), [](double x) { return f64::sf_erfcx(x); },
      [](float x) { return f32::sf_erfcx(x); }, erfcx_reference));
  rows.push_back(scalar_row(
      describe("sf_log_normal_cdf", "t in [-60, 8]", "log of Boost erfc, long double", "relative"),
      linspace(-60.0, 8.0, 2721), linspace(-60.0, 8.0, 2721), [](double t) { return f64::sf_log_normal_cdf(t); },
      [](float t) { return f32::sf_log_normal_cdf(t); }, log_normal_cdf_reference));
  rows.push_back(scalar_row(
      describe("sf_phi_over_Phi", "t in [-60, 8]", "Boost erfc, long double", "relative"), linspace(-60.0, 8.0, 2721),
      linspace(-60.0, 8.0, 2721), [](double t) { return f64::sf_phi_over_Phi(t); },
      [](float t) { return f32::sf_phi_over_Phi(t); },
      [](Real t) { return normal_pdf(t) / std::exp(log_normal_cdf_reference(t)); }));
  rows.push_back(scalar_row(
      describe("gaussian_smith_lambda_of_t", "t in [1e-3, 36] (f32: [1e-3, 12])", "exp-sinh quadrature, long double",
               "relative"),
      linspace(1e-3, 36.0, 721), linspace(1e-3, 12.0, 241), [](double t) { return f64::gaussian_smith_lambda_of_t(t); },
      [](float t) { return f32::gaussian_smith_lambda_of_t(t); }, smith_lambda_reference));
  const char* ndf_names[] = {"Beckmann", "GGX", "Kagiwada-Kalaba", "spherical Gaussian"};
  for (int ndf = 0; ndf < 4; ++ndf) rows.push_back(cross_section_row(context, ndf, ndf_names[ndf]));
  return rows;
}

}  // namespace facet::report
