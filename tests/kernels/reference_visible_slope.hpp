// Brute-force quadrature reference for the visible slope distribution D_s (eqs. 12-23 of
// Heitz et al. 2014, Filtering Non-Linear Transfer Functions on Surfaces, supplemental), independent of the kernel's
// closed forms.
//
// The defining 2D integrals  N = int p_s(s) max(0, W(s)) ds  and the first and central second moments
// of p_s max(0, W)/N are integrated numerically over the whitened coordinates (y, v) of p_s in the view
// frame: s_o = mean_o + sigma_o y, s_perp = mean_perp + (c_op/sigma_o) y + sqrt(|Sigma|)/sigma_o v, with
// p_s ds = phi(y) phi(v) dy dv and W = sin(theta) sigma_o (t - y). For t >= 0 the outer variable is y
// (weight (t - y) phi(y)); beyond the horizon (t < 0) it is u = t - y >= 0 with the weight rescaled by
// exp(t^2/2) so that nothing underflows (log N is returned). Only tails below exp(-700) are cut.
// Two independent nested rules: adaptive Gauss-Kronrod (31 points) and tanh-sinh.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

namespace facet::test {

struct SlopeCase {
  double mean_x, mean_y, var_x, var_y, c_xy, theta, phi;
};

struct SlopeMoments {
  double log_N;
  double mean_x, mean_y, var_x, var_y, c_xy;
};

enum class Quadrature { GaussKronrod, TanhSinh };

// Integral of f over [a, b] to relative tolerance ~1e-13 with the chosen rule; level 0 = outer,
// 1 = inner (tanh-sinh keeps state, so nested calls need their own instance).
template <class F>
double integrate_1d(Quadrature rule, int level, F f, double a, double b) {
  if (rule == Quadrature::GaussKronrod)
    return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, 8, 1e-13);
  static boost::math::quadrature::tanh_sinh<double> tanh_sinh[2] = {boost::math::quadrature::tanh_sinh<double>(12),
                                                                    boost::math::quadrature::tanh_sinh<double>(12)};
  return tanh_sinh[level].integrate(f, a, b, 1e-13);
}

inline SlopeMoments reference_visible_slope(const SlopeCase& k, Quadrature rule) {
  const double c = std::cos(k.phi), s = std::sin(k.phi);
  const double mean_o = k.mean_x * c + k.mean_y * s;
  const double mean_perp = -k.mean_x * s + k.mean_y * c;
  const long double det = static_cast<long double>(k.var_x) * k.var_y - static_cast<long double>(k.c_xy) * k.c_xy;
  const double var_o = k.var_x * c * c + k.var_y * s * s + 2 * k.c_xy * c * s;
  const double cov_op = (k.var_y - k.var_x) * c * s + k.c_xy * (c * c - s * s);
  const double sigma_o = std::sqrt(var_o);
  const double beta_sigma = cov_op / sigma_o;                               // d s_perp / d y
  const double sigma_cond = std::sqrt(static_cast<double>(det)) / sigma_o;  // d s_perp / d v
  const double sin_t = std::sin(k.theta), cos_t = std::cos(k.theta);
  const double a = sin_t * sigma_o;
  const double t = (cos_t - mean_o * sin_t) / a;
  const bool beyond = t < 0;
  // Outer variable q, its range, weight, and s_o, s_perp measured from origins near the mass.
  const double t_scale = std::max(t, 1.0);
  const double q_lo = beyond ? 0.0 : -40.0;
  const double q_hi = beyond ? 800.0 / (1.0 - t) : std::min(t, 40.0);
  auto weight = [&](double q) {
    return beyond ? q * std::exp(q * (t - 0.5 * q)) : (t - q) / t_scale * std::exp(-0.5 * q * q);
  };
  const double origin_o = beyond ? cos_t / sin_t : mean_o;
  const double origin_perp = beyond ? mean_perp + beta_sigma * t : mean_perp;
  // In units of sigma_o (keeps the integrands O(1) for tiny variances).
  auto d_o = [&](double q) { return beyond ? -q : q; };
  auto d_perp = [&](double q, double v) {
    return ((beyond ? -beta_sigma * q : beta_sigma * q) + sigma_cond * v) / sigma_o;
  };
  // v enters through phi(v) only, so the inner integrand is symmetrised onto v >= 0 (keeps odd parts,
  // whose integral is 0, from defeating the relative tolerance).
  auto integrate = [&](auto g) {
    auto outer = [&](double q) {
      const double w = weight(q);
      if (w == 0) return 0.0;
      auto inner = [&](double v) { return std::exp(-0.5 * v * v) * (g(q, v) + g(q, -v)); };
      return w * integrate_1d(rule, 1, inner, 0.0, 40.0);
    };
    // When the horizon is outside the mass (t >= 40) the range [-40, 40] is folded onto [0, 40] so that
    // the odd parts, whose integral is 0, cancel pointwise instead of defeating the relative tolerance.
    if (!beyond && t >= 40.0) {
      auto folded = [&](double q) { return outer(q) + outer(-q); };
      return integrate_1d(rule, 0, folded, 0.0, 40.0) / (2 * std::numbers::pi);
    }
    // Mapped onto [0, 1]: tanh-sinh handles the endpoint 0 exactly, but not every finite a.
    auto mapped = [&](double tau) { return outer(q_lo + (q_hi - q_lo) * tau); };
    return (q_hi - q_lo) * integrate_1d(rule, 0, mapped, 0.0, 1.0) / (2 * std::numbers::pi);
  };
  const double I0 = integrate([](double, double) { return 1.0; });
  const double m_o = integrate([&](double q, double) { return d_o(q); }) / I0;
  const double m_p = integrate([&](double q, double v) { return d_perp(q, v); }) / I0;
  const double v_oo = integrate([&](double q, double) {
                        double e = d_o(q) - m_o;
                        return e * e;
                      }) /
                      I0 * var_o;
  const double v_pp = integrate([&](double q, double v) {
                        double e = d_perp(q, v) - m_p;
                        return e * e;
                      }) /
                      I0 * var_o;
  // E[(s_o - m_o) s_perp]: exactly 0 integrand when uncorrelated (no zero-valued relative tolerance).
  const double v_op = integrate([&](double q, double v) { return (d_o(q) - m_o) * d_perp(q, v); }) / I0 * var_o;
  const double ds_mean_o = origin_o + sigma_o * m_o, ds_mean_p = origin_perp + sigma_o * m_p;
  SlopeMoments r;
  r.log_N = std::log(a) + (beyond ? -0.5 * t * t : std::log(t_scale)) + std::log(I0);
  r.mean_x = ds_mean_o * c - ds_mean_p * s;
  r.mean_y = ds_mean_o * s + ds_mean_p * c;
  r.var_x = v_oo * c * c + v_pp * s * s - 2 * v_op * c * s;
  r.var_y = v_oo * s * s + v_pp * c * c + 2 * v_op * c * s;
  r.c_xy = (v_oo - v_pp) * c * s + v_op * (c * c - s * s);
  return r;
}

}  // namespace facet::test
