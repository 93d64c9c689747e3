// 50-digit references for the double kernels of shaders/lib, computed from their *definitions*
// (integrals evaluated by Boost.Math quadrature in Boost.Multiprecision cpp_bin_float<50>), never from
// the closed forms, recurrences or fits the kernels use. Shared by tests/kernels/kernel_accuracy_test.cpp
// and bench/kernel_accuracy.cpp (which writes docs/kernel_accuracy.md).
//
// Every integral here is of the form int_0^inf P(u) exp(-s u - u^2/2) du, s >= 0, P a polynomial of degree
// <= 4 (or a finite one on [0, 1]), so one cheap rule serves all: 40-point Gauss-Legendre on [0, U] with
// U^2/2 + s U = 80, the neglected tail being below exp(-80) relative. Measured against adaptive exp_sinh
// (ReferencesAgreeWithIndependentMethods): < 1e-22 relative for every s and degree used. A value costs one
// to three such integrals, 0.3-1 ms. The cross-sections of isotropic normal distributions (isotropic_sigma, at the
// end) are integrals over directions with kinks and peaks, taken piecewise.
#pragma once

#include <algorithm>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/log1p.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace facet::test::mp {

// cpp_bin_float_50 without expression templates (the quadrature code wants plain values).
using Real = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;

inline const Real kPi = boost::math::constants::pi<Real>();
inline const Real kSqrtPi = sqrt(kPi);
inline const Real kSqrt2 = sqrt(Real(2));
inline const Real kSqrt2Pi = sqrt(2 * kPi);

// int_0^inf f(u) du for f(u) = P(u) exp(-s u - u^2/2) as above.
template <class F>
Real integrate_gaussian_tail(F f, const Real& s) {
  const Real U = sqrt(s * s + 160) - s;
  return boost::math::quadrature::gauss<Real, 40>::integrate(f, Real(0), U);
}

// --- Error functions, from erfc(x) = 2/sqrt(pi) int_x^inf exp(-u^2) du. ---

// erfcx(x) = exp(x^2) erfc(x) = 2/sqrt(pi) int_0^inf exp(-u^2 - 2 x u) du for x >= 0 (u -> x + u, then
// u = w/sqrt2), which never underflows; for x < 0, erfc(x) = 2 - erfc(-x) (the integrand is even).
inline Real erfcx(const Real& x) {
  if (x < 0) return 2 * exp(x * x) - erfcx(-x);
  const Real s = kSqrt2 * x;
  return kSqrt2 / kSqrtPi * integrate_gaussian_tail([&](const Real& w) { return exp(-w * (s + w / 2)); }, s);
}

inline Real erfc(const Real& x) { return x >= 0 ? exp(-x * x) * erfcx(x) : 2 - erfc(-x); }

// erf(x) = 2/sqrt(pi) int_0^x exp(-u^2) du, taken over u = x s, s in [0, 1] (keeps tiny x relative);
// beyond |x| = 2 as 1 - erfc(|x|) (no cancellation there).
inline Real erf(const Real& x) {
  if (abs(x) > 2) return x > 0 ? 1 - erfc(x) : erfc(-x) - 1;
  return 2 * x / kSqrtPi *
         boost::math::quadrature::gauss<Real, 40>::integrate([&](const Real& s) { return exp(-x * x * s * s); },
                                                             Real(0), Real(1));
}

// Upper normal tail Q(x) = int_x^inf phi and log Phi(t) = log Q(-t); the 50-digit exponent range
// holds exp(-x^2/2) for every double x.
inline Real normal_tail(const Real& x) { return erfc(x / kSqrt2) / 2; }
inline Real normal_pdf(const Real& x) { return exp(-x * x / 2) / kSqrt2Pi; }
// For t > 0 as log(1 - Q(t)): 1 - Q rounds to 1 beyond t = 15 even in 50 digits.
inline Real log_normal_cdf(const Real& t) { return t > 0 ? boost::math::log1p(-normal_tail(t)) : log(normal_tail(-t)); }

// --- Smith masking: Lambda = (N - w0)/w0 with N = E[max(0, W)], w0 = E[W] = a t (eq. 16 of the visible
// slope paper below), i.e. E[max(0, -W)]/(a t) = (1/t) int_0^inf u phi(t + u) du, t > 0. ---
inline Real smith_lambda(const Real& t) {
  return normal_pdf(t) / t * integrate_gaussian_tail([&](const Real& u) { return u * exp(-u * (t + u / 2)); }, t);
}

// --- Visible slopes (Heitz et al. 2014, Filtering Non-Linear Transfer Functions on Surfaces,
// supplemental, eqs. 12-23). ---

struct VisibleSlope {
  Real log_N, mean_x, mean_y, var_x, var_y, c_xy;
};

// D_s(s) = max(0, <omega_o, n(s)>) p(s) / N over slope space, with n(s) = (-s_x, -s_y, 1) the facet normal
// scaled by the facet's area per unit surface area (eq. 12), omega_o = (sin theta cos phi, sin theta sin
// phi, cos theta) and p = N(mean, Sigma). N, the mean and the covariance of D_s are 2D integrals. They are
// taken with a product rule in whitened coordinates s = mean + c_y y + c_v v, (y, v) ~ N(0, I), whose
// first axis is chosen so that <omega_o, n(s)> = a (t - y) depends on y only (c_y, c_v: Cholesky factor of
// Sigma in the frame of (cos phi, sin phi)); the inner rule's moments int v^k phi(v) dv (k <= 2) are
// integrated once, the outer 1D integrals in y per case. For t < 0 the outer variable is u = t - y >= 0
// with exp(-t^2/2) factored out, so nothing is a difference of nearly equal numbers.
inline VisibleSlope visible_slope(double mean_x, double mean_y, double var_x, double var_y, double c_xy, double theta,
                                  double phi) {
  // G_k = int v^k phi(v) dv over the line, as int_0^inf (v^k + (-v)^k) phi(v) dv.
  auto moment = [](int k) {
    return integrate_gaussian_tail([&](const Real& v) { return (pow(v, k) + pow(-v, k)) * normal_pdf(v); }, Real(0));
  };
  static const Real G[4] = {moment(0), moment(1), moment(2), moment(3)};
  const Real c = cos(Real(phi)), s = sin(Real(phi));
  const Real vx = var_x, vy = var_y, cxy = c_xy;
  const Real var_o = vx * c * c + vy * s * s + 2 * cxy * c * s;
  const Real cov_op = (vy - vx) * c * s + cxy * (c * c - s * s);
  const Real sigma_o = sqrt(var_o);
  const Real sigma_c = sqrt(vx * vy - cxy * cxy) / sigma_o;
  // s = mean + y (sigma_o e_o + cov_op/sigma_o e_perp) + v sigma_c e_perp, e_o = (c, s), e_perp = (-s, c).
  const Real cy_x = sigma_o * c - cov_op / sigma_o * s, cy_y = sigma_o * s + cov_op / sigma_o * c;
  const Real cv_x = -sigma_c * s, cv_y = sigma_c * c;
  const Real st = sin(Real(theta)), ct = cos(Real(theta));
  const Real a = st * sigma_o;
  const Real mean_o = Real(mean_x) * c + Real(mean_y) * s;
  const Real t = (ct - mean_o * st) / a;
  // Outer moments Y_k = int max(0, t - y) y^k phi(y) dy (k = 0, 1, 2), as log Y_0, E[y], Var y.
  Real log_Y0, mean_y_w, var_y_w;
  if (t < 0) {
    // y = t - u: Y_k = phi(t) int_0^inf u (t - u)^k exp(t u - u^2/2) du; moments of u, then of y.
    auto J = [&](int k) {
      return integrate_gaussian_tail([&](const Real& u) { return pow(u, k + 1) * exp(u * (t - u / 2)); }, -t);
    };
    const Real J0 = J(0), J1 = J(1), J2 = J(2);
    log_Y0 = log(J0) - t * t / 2 - log(kSqrt2Pi);
    mean_y_w = t - J1 / J0;
    var_y_w = J2 / J0 - (J1 / J0) * (J1 / J0);
  } else {
    // int_{-inf}^t = int_R - int_t^inf, the latter with y = t + u and phi(t + u) = phi(t) exp(-t u - u^2/2).
    auto Y = [&](int k) {
      const Real tail =
          integrate_gaussian_tail([&](const Real& u) { return u * pow(t + u, k) * exp(-u * (t + u / 2)); }, t);
      return t * G[k] - G[k + 1] + normal_pdf(t) * tail;
    };
    const Real Y0 = Y(0), Y1 = Y(1), Y2 = Y(2);
    log_Y0 = log(Y0);
    mean_y_w = Y1 / Y0;
    var_y_w = Y2 / Y0 - mean_y_w * mean_y_w;
  }
  const Real mean_v = G[1] / G[0], var_v = G[2] / G[0] - mean_v * mean_v;
  VisibleSlope r;
  r.log_N = log(a) + log_Y0 + log(G[0]);
  r.mean_x = mean_x + cy_x * mean_y_w + cv_x * mean_v;
  r.mean_y = mean_y + cy_y * mean_y_w + cv_y * mean_v;
  r.var_x = cy_x * cy_x * var_y_w + cv_x * cv_x * var_v;
  r.var_y = cy_y * cy_y * var_y_w + cv_y * cv_y * var_v;
  r.c_xy = cy_x * cy_y * var_y_w + cv_x * cv_y * var_v;
  return r;
}

// --- Cross-sections sigma(u) = int D(m) max(0, m.w) dm of isotropic normal distributions (docs/cross_sections.md),
// w = (s, 0, u), s = sqrt(1 - u^2), D per steradian as a function of the polar angle g of m. ---

// In spherical coordinates (g, phi) about z, m.w = a + c cos phi with a = u cos g, c = s sin g, and the azimuthal
// integral of the clipped cosine is elementary: K = int_0^{2 pi} max(0, a + c cos phi) dphi = 2 pi a (a >= c), 0
// (a <= -c), else 2 (a phi0 + sqrt(c^2 - a^2)) with phi0 = atan2(sqrt(c^2 - a^2), -a). So
//   sigma = int_0^G D(g) K(g) sin g dg,
// G the end of D's support. c^2 - a^2 = -cos(g + theta) cos(g - theta) vanishes at the kinks k1 = |asin u| and
// k2 = pi - k1, where K is (g - k)^(3/2)-singular, and at their mirrors -k1, pi + k1: a piece ending at a kink is
// integrated in y with g - k ~ y^2 (smooth in y), and the pieces inside (k1, k2) are graded away from the kinks at
// delta 2^j, delta ~ min(2 k1, scale(k)) (the mirror's distance; D's own scale there). D peaks at g = peak with the
// given width: the pieces are also graded at peak +- width 2^j. Points-point Gauss-Legendre per piece, 20 by default:
// against 40 points, < 1e-20 relative (KernelAccuracy.ReferencesAgreeWithIndependentMethods). Only elementary
// functions: independent of the kernels' closed forms and of the Bessel reduction that sg_cross_section_exact
// integrates. 2-10 ms a value.
template <int Points, class Density, class Scale>
Real isotropic_sigma(Density D, Scale scale, const Real& u, const Real& peak, const Real& width, const Real& support) {
  const Real s = sqrt((1 - u) * (1 + u));
  const Real k1 = abs(asin(u)), k2 = kPi - k1;
  std::vector<Real> breaks = {Real(0), support};
  auto add = [&](const Real& g) {
    if (g > 0 && g < support) breaks.push_back(g);
  };
  add(k1);
  add(k2);
  // Grading away from the kinks, both ways (D may fall fast there, e.g. the spherical Gaussian below the horizon),
  // from half the distance to the nearest other singularity: the other kink, the mirror (2 k1 away; but not below
  // min(1, scale(k))/200: where it is closer, the part of K it bends is O(k1^2) of a piece of weight O(delta^2)) or
  // D's own scale(k); at most pi/8.
  Real delta[2];
  for (int side = 0; side < 2; ++side) {
    const Real k = side == 0 ? k1 : k2, sc = scale(k);
    const Real mirror = std::max<Real>(2 * k1, std::min<Real>(1, sc) / 200);
    delta[side] = std::min<Real>(k1 < k2 ? std::min({mirror, k2 - k1, sc}) : sc, kPi / 4) / 2;
    for (Real d = delta[side]; d < support; d *= 2) {
      add(k - d);
      add(k + d);
    }
  }
  // The peak's grading, and pieces of at most pi/8.
  for (Real d = width; d < support; d *= 2) {
    add(peak - d);
    add(peak + d);
  }
  for (int j = 1; j < 8; ++j) add(kPi * j / 8);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  // No inner break closer to a kink than half its first step (the piece beyond would start next to the kink's
  // singularity without the substitution that smooths it).
  std::erase_if(breaks, [&](const Real& g) {
    if (g == 0 || g == support || g == k1 || g == k2) return false;
    const Real d1 = abs(g - k1), d2 = abs(g - k2);
    return (d1 > 0 && d1 < delta[0] / 2) || (d2 > 0 && d2 < delta[1] / 2);
  });
  auto integrand = [&](const Real& g) {
    const Real h = sin(g / 2), sin_g = 2 * h * sqrt(1 - h * h);
    const Real a = u * (1 - 2 * h * h), c = s * sin_g;
    Real K;
    if (a >= c)
      K = 2 * kPi * a;
    else if (a <= -c)
      return Real(0);
    else {
      const Real root = sqrt(c * c - a * a);
      K = 2 * (a * atan2(root, -a) + root);
    }
    return D(h) * K * sin_g;
  };
  Real sum = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const Real l = breaks[i], r = breaks[i + 1], h = r - l;
    if (u < 0 && r <= k1) continue;  // K = 0 there
    const bool kink_l = l == k1 || l == k2, kink_r = r == k1 || r == k2;
    auto piece = [&](const Real& y) {
      if (kink_l && kink_r) return integrand(l + h * y * y * (3 - 2 * y)) * 6 * h * y * (1 - y);
      if (kink_l) return integrand(l + h * y * y) * 2 * h * y;
      if (kink_r) return integrand(r - h * (1 - y) * (1 - y)) * 2 * h * (1 - y);
      return integrand(l + h * y) * h;
    };
    sum += boost::math::quadrature::gauss<Real, Points>::integrate(piece, Real(0), Real(1));
  }
  return sum;
}

// GGX: D = alpha^2 / (pi (alpha^2 cos^2 g + sin^2 g)^2) on the upper hemisphere (normalised by int D m_z dm = 1),
// peaked at g = 0 (width alpha) for alpha < 1, at the horizon (width 1/alpha) for alpha > 1.
template <int Points = 20>
Real ggx_sigma(double alpha, double u) {
  const Real a2 = Real(alpha) * alpha;
  auto D = [&](const Real& h) {  // cos^2 g = (1 - 2 h^2)^2, sin^2 g = 4 h^2 (1 - h^2)
    const Real c = 1 - 2 * h * h, q = a2 * c * c + 4 * h * h * (1 - h * h);
    return a2 / (kPi * q * q);
  };
  const Real width = alpha < 1 ? Real(alpha) : 1 / Real(alpha);
  return isotropic_sigma<Points>(
      D, [&](const Real&) { return width; }, u, alpha < 1 ? Real(0) : kPi / 2, width, kPi / 2);
}

// Kagiwada-Kalaba: D = b / (2 pi L (1 - b cos g)), L = log((1 + b)/(1 - b)), 1 - b cos g = (1 - b) + 2 b sin^2(g/2);
// peak width sqrt((1 - b)/b).
template <int Points = 20>
Real kk_sigma(double b, double u) {
  const Real B = b, L = log((1 + B) / (1 - B));
  auto D = [&](const Real& h) { return B / (2 * kPi * L * ((1 - B) + 2 * B * h * h)); };
  const Real width = sqrt((1 - B) / B);
  return isotropic_sigma<Points>(
      D, [&](const Real&) { return width; }, u, Real(0), width, kPi);
}

// Spherical Gaussian (vMF, kappa = 2/alpha^2): D = kappa exp(-2 kappa sin^2(g/2)) / (2 pi (1 - exp(-2 kappa))).
template <int Points = 20>
Real sg_sigma(double alpha, double u) {
  const Real kappa = 2 / (Real(alpha) * alpha);
  const Real scale = kappa / (2 * kPi * (1 - exp(-2 * kappa)));
  auto D = [&](const Real& h) { return scale * exp(-2 * kappa * h * h); };
  // exp(-2 kappa sin^2(g/2)) falls by e over 1/(kappa sin g) at g.
  const Real width = 1 / sqrt(kappa);
  return isotropic_sigma<Points>(
      D, [&](const Real& g) { return std::min<Real>(width, 1 / (kappa * sin(g))); }, u, Real(0), width, kPi);
}

}  // namespace facet::test::mp
