// Brute-force references for the colour-map filtering tests: composite 30-point Gauss–Legendre quadrature in long
// double (Boost.Math) of a linear colour ramp against a Gaussian, independent of the closed form.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss.hpp>
#include <glm/glm.hpp>

#include "scene/colormap.hpp"

namespace facet::test {

using LongVec3 = glm::tvec3<long double>;

// Integral over [x0, x1] of c0 + (c1 - c0)(x - x0)/(x1 - x0) times the N(mu, sigma^2) density. In
// z = (x - mu)/sigma the interval is mirrored to lie mostly left of 0 and written relative to its end
// hi closest to 0, phi(hi + v) = phi(hi) exp(-hi v - v^2/2), so far tails keep relative accuracy
// (the factor phi(hi) is applied last; long double reaches phi(150)). The range is cut into pieces of at
// most one decay length min(1, 1/|hi|) (at most 128 pieces) of an entire integrand, on which 30
// Gauss-Legendre nodes are exact to long-double rounding.
inline LongVec3 segment_reference(long double x0, long double x1, LongVec3 c0, LongVec3 c1, long double mu,
                                  long double sigma) {
  long double a = (x0 - mu) / sigma, b = (x1 - mu) / sigma;
  const bool mirror = a + b > 0;
  if (mirror) {
    std::swap(a, b);
    a = -a;
    b = -b;
    std::swap(c0, c1);
  }
  const long double hi = b;
  const long double scale = hi < 0 ? std::exp(-hi * hi / 2) : 1.0L;
  const long double shift = hi < 0 ? hi : 0.0L;
  // Beyond this distance from `shift` the integrand is below exp(-112) of its peak (for hi < 0,
  // exp(-hi v - v^2/2) <= exp(-v^2/2) on v <= 0).
  const long double reach = hi < 0 ? 15.0L : 40.0L;
  const long double v_lo = std::max(a - shift, -reach), v_hi = std::min(b - shift, reach);
  if (!(v_hi > v_lo)) return LongVec3(0);
  LongVec3 out(0);
  for (int channel = 0; channel < 3; ++channel) {
    auto integrand = [&](long double v) {
      const long double z = v + shift;
      const long double f = (z - a) / (b - a);
      const long double colour = c0[channel] + (c1[channel] - c0[channel]) * f;
      const long double density = hi < 0 ? std::exp(-hi * v - v * v / 2) : std::exp(-z * z / 2);
      return colour * density;
    };
    long double sum = 0;
    const long double decay = hi < -1 ? 1 / -hi : 1.0L;
    const int pieces = static_cast<int>(std::min(128.0L, std::ceil((v_hi - v_lo) / decay)));
    for (int p = 0; p < pieces; ++p) {
      const long double l = v_lo + (v_hi - v_lo) * p / pieces, r = v_lo + (v_hi - v_lo) * (p + 1) / pieces;
      sum += boost::math::quadrature::gauss<long double, 30>::integrate(integrand, l, r);
    }
    out[channel] = sum * scale / std::sqrt(2 * std::numbers::pi_v<long double>);
  }
  return out;
}

// E[map(v)] for v ~ N(mu, sigma^2), summed segment by segment (breakpoints at the control points) with
// the constant tails as 1D quadratures too.
inline LongVec3 colormap_reference(const Colormap& map, long double mu, long double sigma) {
  const long double lo = map.domain().x, width = map.domain().y - map.domain().x;
  const auto& x = map.positions();
  const auto& c = map.colours();
  const bool steps = map.interpolation() == Colormap::Interpolation::Steps;
  auto value = [&](long double t) { return lo + width * t; };
  const long double far = 1e4L * (sigma + 1);
  LongVec3 sum =
      segment_reference(value(x.front()) - far, value(x.front()), LongVec3(c.front()), LongVec3(c.front()), mu, sigma) +
      segment_reference(value(x.back()), value(x.back()) + far, LongVec3(c.back()), LongVec3(c.back()), mu, sigma);
  for (std::size_t k = 0; k + 1 < x.size(); ++k)
    sum +=
        segment_reference(value(x[k]), value(x[k + 1]), LongVec3(c[k]), LongVec3(steps ? c[k] : c[k + 1]), mu, sigma);
  return sum;
}

}  // namespace facet::test
