// The per-pixel microsurface model (shaders/lib/microsurface_filter.glsl) against brute-force
// quadrature written here: the visible-height rule, the visible-slope integral with the cosine term,
// the LEAN-convolved Beckmann lobe; the float twin against the double twin; extreme inputs finite.
// Derivation and measured errors: docs/microsurface_filtering.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "kernels/shared.hpp"

namespace facet {
namespace {

namespace k64 = kernels::f64;
namespace k32 = kernels::f32;

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// A piecewise-linear "colour" of the height with kinks inside the visible range, like a terrain map.
double terrain(double h) {
  const double x[] = {-0.03, 0.0, 0.012, 0.016, 0.05}, y[] = {0.1, 0.45, 0.5, 0.95, 0.95};
  if (h <= x[0]) return y[0];
  for (int i = 0; i < 4; ++i)
    if (h <= x[i + 1]) return y[i] + (y[i + 1] - y[i]) * (h - x[i]) / (x[i + 1] - x[i]);
  return y[4];
}

// E[g(h)] for the law with CDF Phi((h - mean)/sigma)^(1 + lambda), as the Stieltjes sum of g at
// midpoints against CDF increments on 2e5 cells of z in [-12, 12].
double brute_height_mean(const std::function<double(double)>& g, double mean, double sigma, double lambda) {
  const int n = 200000;
  double sum = 0.0, prev = 0.0;
  for (int i = 1; i <= n; ++i) {
    const double z = -12.0 + 24.0 * i / n;
    const double cdf = std::exp((1.0 + lambda) * std::log(normal_cdf(z)));
    sum += g(mean + sigma * (z - 12.0 / n)) * (cdf - prev);
    prev = cdf;
  }
  return sum;
}

double node_height_mean(const std::function<double(double)>& g, double mean, double sigma, double lambda) {
  double sum = 0.0;
  for (int k = 0; k < MS_HEIGHT_NODES; ++k) sum += g(k64::microsurface_height_node(k, mean, sigma, lambda));
  return sum / MS_HEIGHT_NODES;
}

// The visible heights of the terrain map for the terrain scene's sigma_h = 12 mm: the 8-node midpoint
// rule in u = C^(1 + Lambda) against the brute-force Stieltjes sum, for Lambda from 0 to 1e4.
TEST(MicrosurfaceFilter, VisibleHeightRuleMatchesQuadrature) {
  double worst = 0.0;
  for (double mean : {-0.01, 0.0, 0.006})
    for (double lambda : {0.0, 0.3, 3.0, 30.0, 1e4}) {
      const double exact = brute_height_mean(terrain, mean, 0.012, lambda);
      const double nodes = node_height_mean(terrain, mean, 0.012, lambda);
      worst = std::max(worst, std::abs(nodes - exact));
      // Smooth integrand: the rule converges like K^-2 (midpoint) on a smooth g(h(u)).
      const auto smooth = [](double h) { return std::tanh(40.0 * h); };
      EXPECT_NEAR(node_height_mean(smooth, mean, 0.012, lambda), brute_height_mean(smooth, mean, 0.012, lambda), 0.02)
          << mean << " " << lambda;
    }
  std::printf("visible-height rule, terrain map: worst |error| %.2e (map range 0.85)\n", worst);
  EXPECT_LT(worst, 0.02);
}

// E_vis[g C^Lambda_l] = lit E_{C^(1 + Lambda_v + Lambda_l)}[g] (the lit-height identity of the shader),
// against the brute-force integral of g (1 + Lambda_v) C^Lambda_v c C^Lambda_l.
TEST(MicrosurfaceFilter, LitHeightsFollowTheCombinedLambda) {
  double worst = 0.0;
  for (double lv : {0.0, 0.5, 5.0})
    for (double ll : {0.0, 0.2, 0.9, 4.0, 50.0}) {
      const int n = 200000;
      double exact = 0.0, prev = 0.0;
      for (int i = 1; i <= n; ++i) {
        const double z = -12.0 + 24.0 * i / n, zm = z - 12.0 / n;
        const double cdf = std::exp((1.0 + lv) * std::log(normal_cdf(z)));
        exact += terrain(0.012 * zm) * std::exp(ll * std::log(normal_cdf(zm))) * (cdf - prev);
        prev = cdf;
      }
      // As the shader: the visible nodes with product weights while a <= MS_LIT_SHARED_MAX, else the
      // nodes of the combined Lambda.
      const double lit = (1.0 + lv) / (1.0 + lv + ll), a = ll / (1.0 + lv);
      double rule = 0.0;
      if (a <= k64::MS_LIT_SHARED_MAX)
        for (int k = 0; k < MS_HEIGHT_NODES; ++k)
          rule += k64::microsurface_lit_weight(k, a) * terrain(k64::microsurface_height_node(k, 0.0, 0.012, lv));
      else
        rule = node_height_mean(terrain, 0.0, 0.012, lv + ll);
      worst = std::max(worst, std::abs(lit * rule - exact));
      EXPECT_NEAR(lit * rule, exact, 0.02) << lv << " " << ll;
    }
  std::printf("lit heights: worst |error| %.2e\n", worst);
}

struct SlopeCase {
  glm::dvec2 mean;
  glm::dvec3 cov;
  double theta, phi;
};

// E_Ds[f] = int W+ p_s f / int W+ p_s by a 600 x 600 midpoint grid over +-7 sigma (principal axes).
double brute_slope_mean(const std::function<double(glm::dvec2)>& f, const SlopeCase& c) {
  const double tr = c.cov.x + c.cov.y, det = c.cov.x * c.cov.y - c.cov.z * c.cov.z;
  const double l1 = 0.5 * tr + std::sqrt(0.25 * tr * tr - det), l2 = std::max(tr - l1, 0.0);
  const double angle = 0.5 * std::atan2(2.0 * c.cov.z, c.cov.x - c.cov.y);
  const glm::dvec2 e1(std::cos(angle), std::sin(angle)), e2(-e1.y, e1.x);
  const int n = 600;
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = -7.0 + 14.0 * (i + 0.5) / n, b = -7.0 + 14.0 * (j + 0.5) / n;
      const glm::dvec2 s = c.mean + a * std::sqrt(l1) * e1 + b * std::sqrt(l2) * e2;
      const double w = std::cos(c.theta) - std::sin(c.theta) * (s.x * std::cos(c.phi) + s.y * std::sin(c.phi));
      if (w <= 0.0) continue;
      const double p = std::exp(-0.5 * (a * a + b * b));
      num += w * p * f(s);
      den += w * p;
    }
  return num / den;
}

double node_slope_mean(const std::function<double(glm::dvec2)>& f, const SlopeCase& c, int order = MS_SLOPE_NODES) {
  const k64::VisibleSlope ds = k64::visible_slope(c.mean, c.cov, c.theta, c.phi);
  double sum = 0.0;
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) {
      const k64::MicrosurfaceSlopeNode node = k64::microsurface_slope_node(ds, order, i, j);
      sum += node.weight * f(node.s);
    }
  return sum;
}

// The slope integrals of the shader (the cosine to the light and a slope colour ramp, each against D_s)
// by the 4 x 4 Gauss-Hermite grid (and the cosine alone by the 3 x 3 one) over the Gaussian
// approximation of D_s, against brute force over the exact D_s. The approximation (not the grid) dominates at grazing
// views.
TEST(MicrosurfaceFilter, VisibleSlopeIntegralsMatchQuadrature) {
  const glm::dvec3 l = glm::normalize(glm::dvec3(0.4, 0.3, 0.8));
  const auto cosine = [&](glm::dvec2 s) { return std::max(glm::dot(k64::microsurface_normal(s), l), 0.0); };
  const auto ramp = [](glm::dvec2 s) { return std::min(glm::length(s) / 1.2, 1.0); };  // viridis-like domain
  const SlopeCase cases[] = {
      {{0.0, 0.0}, {0.22, 0.22, 0.0}, 0.0, 0.0},   {{0.0, 0.0}, {0.22, 0.22, 0.0}, 1.0, 0.3},
      {{0.0, 0.0}, {0.22, 0.22, 0.0}, 1.35, -1.2}, {{0.1, -0.2}, {0.05, 0.3, 0.06}, 0.8, 2.0},
      {{0.0, 0.0}, {0.01, 0.01, 0.0}, 1.5, 0.0},   {{0.3, 0.0}, {0.02, 0.004, 0.0}, 1.2, 3.1},
  };
  double worst_cos = 0.0, worst_ramp = 0.0, worst_cos3 = 0.0;
  for (const SlopeCase& c : cases) {
    worst_cos = std::max(worst_cos, std::abs(node_slope_mean(cosine, c) - brute_slope_mean(cosine, c)));
    worst_cos3 =
        std::max(worst_cos3, std::abs(node_slope_mean(cosine, c, MS_SLOPE_NODES_COSINE) - brute_slope_mean(cosine, c)));
    worst_ramp = std::max(worst_ramp, std::abs(node_slope_mean(ramp, c) - brute_slope_mean(ramp, c)));
  }
  std::printf("visible-slope integrals: worst |error| cosine %.2e (3 x 3 rule %.2e), slope ramp %.2e\n", worst_cos,
              worst_cos3, worst_ramp);
  EXPECT_LT(worst_cos, 0.03);
  // The 3 x 3 rule the shader takes without a slope colour map: the smooth cosine alone. Its bound is a
  // third of the ramp's, which the Gaussian approximation of D_s (not the rule) sets.
  EXPECT_LT(worst_cos3, 0.01);
  EXPECT_LT(worst_ramp, 0.03);
}

// LEAN: the footprint's slope Gaussian convolved with the lobe's N(0, alpha^2/2) is N(mean, Sigma +
// alpha^2/2) exactly; checked by brute-force convolution in slope space, and for a flat footprint the
// lobe is the Beckmann D G2/(4 cos_o) of ndf_beckmann.glsl.
// Beckmann's Smith Lambda and the facet lobe f cos_i = D G2 / (4 cos_o), written here from the definitions
// (erfc form of Lambda), for unit l, v in the frame whose normal is z.
double beckmann_lambda(glm::dvec3 w, glm::dvec2 alpha) {
  const double a = w.z / std::sqrt(alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y);
  return 0.5 * (std::exp(-a * a) / (a * std::sqrt(M_PI)) - std::erfc(a));
}
double beckmann_density(glm::dvec3 h, glm::dvec2 alpha) {  // per steradian of h
  const double tx = h.x / h.z, ty = h.y / h.z;
  return std::exp(-tx * tx / (alpha.x * alpha.x) - ty * ty / (alpha.y * alpha.y)) /
         (M_PI * alpha.x * alpha.y * std::pow(h.z, 4));
}

// The footprint's facets N(s; mean, Sigma) with each facet's own Beckmann lobe rotated into its frame (tangent
// the x axis projected on it) and its own G2 there, 0 where l or v lies below the facet, on an n x n grid over
// +-8 standard deviations of Sigma: the integral of eq. M8' (docs/microsurface_filtering.md),
// int p(s) D_alpha(h | m(s)) G2_alpha(l, v | m(s)) ds.
double brute_facet_lobes(glm::dvec2 mean, glm::dvec3 cov, glm::dvec2 alpha, glm::dvec3 l, glm::dvec3 v, int n) {
  const double sx = std::sqrt(cov.x), sy = std::sqrt(cov.y), det = cov.x * cov.y - cov.z * cov.z;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::dvec2 d(-8.0 * sx + 16.0 * sx * (i + 0.5) / n, -8.0 * sy + 16.0 * sy * (j + 0.5) / n);
      const double q = (cov.y * d.x * d.x - 2 * cov.z * d.x * d.y + cov.x * d.y * d.y) / det;
      const glm::dvec2 s = mean + d;
      const glm::dvec3 m = glm::normalize(glm::dvec3(-s.x, -s.y, 1.0));
      const glm::dvec3 t = glm::normalize(glm::dvec3(1, 0, 0) - m.x * m), b = glm::cross(m, t);
      const glm::dvec3 wl(glm::dot(l, t), glm::dot(l, b), glm::dot(l, m)),
          wv(glm::dot(v, t), glm::dot(v, b), glm::dot(v, m));
      if (wl.z <= 0.0 || wv.z <= 0.0) continue;
      const double lobe = beckmann_density(glm::normalize(wl + wv), alpha) /
                          (1.0 + beckmann_lambda(wl, alpha) + beckmann_lambda(wv, alpha));
      sum += std::exp(-0.5 * q) / (2 * M_PI * std::sqrt(det)) * lobe * (16 * sx / n) * (16 * sy / n);
    }
  return sum;
}

// Eq. M8 with M8': f cos_i = G2_field(Sigma) int p(s) D_alpha(h | m(s)) G2_alpha ds / (4 cos_o), the integral
// by the law of the facet slope given h, 3 Gauss-Hermite nodes along the facets' horizons and a truncated 2-point
// rule across them.
TEST(MicrosurfaceFilter, SpecularLobeIsTheFacetsOwnLobesOverTheFootprint) {
  const glm::dvec2 alpha(0.05, 0.2);
  const glm::dvec3 l = glm::normalize(glm::dvec3(-0.6, 0.5, 0.4)), v = glm::normalize(glm::dvec3(0.5, -0.3, 0.6));
  // A point footprint: the plane's own Beckmann lobe.
  const k64::MicrosurfaceStatistics flat{0.0, 1e-9, {0.0, 0.0}, {1e-12, 1e-12, 0.0}};
  const double beckmann = beckmann_density(glm::normalize(l + v), alpha) /
                          (1.0 + beckmann_lambda(l, alpha) + beckmann_lambda(v, alpha)) / (4.0 * v.z);
  EXPECT_NEAR(k64::microsurface_specular(flat, alpha, l, v, glm::dvec4(0.0)) / beckmann, 1.0, 1e-6);
  // A point footprint on a tilted facet: that facet's lobe in its own frame (the reference's), not sheared; the
  // cosine of the view stays the frame's (filtered's frame is the mean facet's, where the slope is 0).
  const k64::MicrosurfaceStatistics tilted{0.0, 1e-9, {0.25, -0.15}, {1e-12, 1e-12, 0.0}};
  const glm::dvec3 m = glm::normalize(glm::dvec3(-0.25, 0.15, 1.0));
  const double facet = k64::beckmann_facet_specular(m, glm::dvec3(1, 0, 0), v, l, alpha) * glm::dot(v, m) / v.z;
  const double g_point =
      k64::gaussian_smith_g2(tilted.s_mean, tilted.s_cov, k64::microsurface_angles(l).x, k64::microsurface_angles(l).y,
                             k64::microsurface_angles(v).x, k64::microsurface_angles(v).y);
  EXPECT_NEAR(k64::microsurface_specular(tilted, alpha, l, v, glm::dvec4(0.0)) / (facet * g_point), 1.0, 1e-5);

  struct Case {
    const char* name;
    k64::MicrosurfaceStatistics stats;
    glm::dvec2 alpha;
    glm::dvec3 l, v;
    double tolerance;  // of the 4 x 2 rule against the n x n grid (measured in the comment)
  };
  // A direction `radians` above the plane, toward +y (side 1) or -y (side -1).
  const auto up = [](double radians, double side) {
    return glm::dvec3(0.0, side * std::cos(radians), std::sin(radians));
  };
  const double e5 = 5.0 * M_PI / 180.0;
  const k64::MicrosurfaceStatistics steep{0.0, 0.01, {0.0, 0.0}, {0.22, 0.22, 0.0}};
  const Case cases[] = {
      // moderate angles, a correlated footprint (measured 0.3 %)
      {"moderate", {0.0, 0.01, {0.05, -0.1}, {0.02, 0.05, 0.01}}, alpha, l, v, 0.01},
      // lobe wider than the footprint's slopes (0.1 %)
      {"wide lobe", {0.0, 0.01, {0.0, 0.0}, {0.01, 0.01, 0.0}}, glm::dvec2(0.3), l, v, 0.01},
      // 5 degrees above the plane on both sides, mirrored: the facets that keep both above their horizon are
      // a strip narrower than the law of the facets under h (1.1 %); with the anisotropic lobe across it (2.1 %)
      {"grazing mirror", {0.0, 0.01, {0.0, 0.0}, {0.08, 0.08, 0.0}}, glm::dvec2(0.3), up(e5, -1), up(e5, 1), 0.04},
      {"grazing anisotropic", {0.0, 0.01, {0.0, 0.0}, {0.08, 0.02, 0.01}}, alpha, up(e5, -1), up(e5, 1), 0.04},
      // a steep field (slopes' deviation 0.47) seen 2 and 6 degrees above the plane, lit 24 degrees up from the
      // far side, as microsurface_horizon's far rows: the view's horizon cuts the law on one side, where the
      // 2-point rule's kink is least resolved (4.6 %, 5.1 %; eq. M8 alone 1.65x, 1.40x)
      {"steep field, grazing view", steep, glm::dvec2(0.3), up(0.42, -1), up(0.035, 1), 0.07},
      {"steep field, view 6 deg", steep, glm::dvec2(0.3), up(0.42, -1), up(0.1, 1), 0.07},
  };

  for (const Case& c : cases) {
    const glm::dvec2 vl = k64::microsurface_angles(c.l), vv = k64::microsurface_angles(c.v);
    const double g2 = k64::gaussian_smith_g2(c.stats.s_mean, c.stats.s_cov, vl.x, vl.y, vv.x, vv.y);
    const double expected =
        g2 * brute_facet_lobes(c.stats.s_mean, c.stats.s_cov, c.alpha, c.l, c.v, 1200) / (4.0 * c.v.z);
    const double got = k64::microsurface_specular(c.stats, c.alpha, c.l, c.v, glm::dvec4(0.0));
    // For comparison, eq. M8 alone (the convolved lobe with the convolved Gaussian's G2, no facet frames).
    const glm::dvec3 both = c.stats.s_cov + glm::dvec3(0.5 * c.alpha.x * c.alpha.x, 0.5 * c.alpha.y * c.alpha.y, 0.0);
    const double lean =
        k64::microsurface_slope_ndf(glm::normalize(c.l + c.v), c.stats.s_mean, both, 0.0, glm::dvec4(0.0)) *
        k64::gaussian_smith_g2(c.stats.s_mean, both, vl.x, vl.y, vv.x, vv.y) / (4.0 * c.v.z);
    std::printf("%s: model / brute force %.4f (eq. M8 alone %.4f)\n", c.name, got / expected, lean / expected);
    EXPECT_NEAR(got / expected, 1.0, c.tolerance) << c.name;
  }
}

// A zero-variance footprint is a point: every slope node sits on the slope, every height node on the
// height, nothing is masked or shadowed (unless grazing).
TEST(MicrosurfaceFilter, ZeroVarianceIsThePoint) {
  const glm::dvec4 m0(0.004, 0.004 * 0.004, 0.3, -0.2), m1(0.09, 0.04, -0.06, 0.0);
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.2, 0.5, 0.7)), l = glm::normalize(glm::dvec3(-0.3, 0.2, 0.8));
  for (int pass = 0; pass < 2; ++pass) {
    const double tol = pass == 0 ? 1e-5 : 1e-4;
    const auto check = [&](auto stats, auto vis, auto node00, auto h0) {
      EXPECT_NEAR(vis.lit, 1.0, tol);
      EXPECT_NEAR(node00.s.x, 0.3, tol);
      EXPECT_NEAR(node00.s.y, -0.2, tol);
      EXPECT_NEAR(h0, 0.004, tol);
      EXPECT_GT(stats.h_sigma, 0.0);
    };
    if (pass == 0) {
      const auto s = k64::microsurface_statistics(m0, m1);
      const auto vis = k64::microsurface_visibility(s, v, l);
      check(s, vis, k64::microsurface_slope_node(vis.ds, MS_SLOPE_NODES, 0, 0),
            k64::microsurface_height_node(0, s.h_mean, s.h_sigma, vis.lambda_v));
    } else {
      const auto s = k32::microsurface_statistics(glm::vec4(m0), glm::vec4(m1));
      const auto vis = k32::microsurface_visibility(s, glm::vec3(v), glm::vec3(l));
      check(s, vis, k32::microsurface_slope_node(vis.ds, MS_SLOPE_NODES, 0, 0),
            k32::microsurface_height_node(0, s.h_mean, s.h_sigma, vis.lambda_v));
    }
  }
}

struct Inputs {
  glm::dvec4 m0, m1;
  glm::dvec3 v, l;
};

// The float twin follows the double twin on the scenes' range of inputs: moments of fields with
// sigma_h ~ 1 cm and slopes ~ 0.5, views from normal to 85 degrees.
TEST(MicrosurfaceFilter, FloatTwinFollowsDouble) {
  double worst_lambda = 0.0, worst_node = 0.0, worst_height = 0.0, worst_spec = 0.0;
  int saturated = 0;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 5; ++b) {
      const double theta = a * 0.28, phi = b * 1.3;
      const glm::dvec3 v(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const glm::dvec3 l = glm::normalize(glm::dvec3(-0.6, 0.5, 0.4 + 0.1 * b));
      const double sx = 0.1 * (b - 2), sy = 0.05 * a, vx = 0.02 + 0.05 * a, vy = 0.3 - 0.04 * b,
                   c = 0.3 * std::sqrt(vx * vy);
      const glm::dvec4 m0(0.001 * a, 1e-4 + 1e-6 * a * a, sx, sy), m1(vx + sx * sx, vy + sy * sy, c + sx * sy, 0.0);
      const auto s64 = k64::microsurface_statistics(m0, m1);
      const auto s32 = k32::microsurface_statistics(glm::vec4(m0), glm::vec4(m1));
      const auto vis64 = k64::microsurface_visibility(s64, v, l);
      const auto vis32 = k32::microsurface_visibility(s32, glm::vec3(v), glm::vec3(l));
      // A mean plane facing away saturates Lambda at exp(69) (float) and exp(690) (double): both mean
      // "all masked" and place the visible heights far beyond any colour map; not compared.
      if (vis64.lambda_v > 1e20 || vis64.lambda_l > 1e20) {
        ++saturated;
        continue;
      }
      worst_lambda = std::max({worst_lambda, std::abs(vis32.lambda_v - vis64.lambda_v) / (1.0 + vis64.lambda_v),
                               std::abs(vis32.lit - vis64.lit)});
      for (int i = 0; i < MS_SLOPE_NODES; ++i)
        for (int j = 0; j < MS_SLOPE_NODES; ++j)
          worst_node = std::max(worst_node,
                                glm::length(glm::dvec2(k32::microsurface_slope_node(vis32.ds, MS_SLOPE_NODES, i, j).s) -
                                            k64::microsurface_slope_node(vis64.ds, MS_SLOPE_NODES, i, j).s));
      for (int k = 0; k < MS_HEIGHT_NODES; ++k)
        worst_height =
            std::max(worst_height, std::abs(k32::microsurface_height_node(k, s32.h_mean, s32.h_sigma, vis32.lambda_v) -
                                            k64::microsurface_height_node(k, s64.h_mean, s64.h_sigma, vis64.lambda_v)) /
                                       s64.h_sigma);
      const glm::dvec2 alpha(0.05, 0.2);
      const double spec64 = k64::microsurface_specular(s64, alpha, l, v, glm::dvec4(0.0));
      const double spec32 =
          k32::microsurface_specular(s32, glm::vec2(alpha), glm::vec3(l), glm::vec3(v), glm::vec4(0.0f));
      worst_spec = std::max(worst_spec, std::abs(spec32 - spec64) / std::max(spec64, 1e-3));
    }
  std::printf(
      "float vs double: Lambda/lit %.1e, slope nodes %.1e, height nodes %.1e sigma_h, specular %.1e"
      " (%d of 30 saturated)\n",
      worst_lambda, worst_node, worst_height, worst_spec, saturated);
  EXPECT_LE(saturated, 6);
  // float eps 6e-8 times the condition of each step (t up to ~1e2 amplifies, Newton quantile to 1e-5).
  EXPECT_LT(worst_lambda, 1e-4);
  EXPECT_LT(worst_node, 1e-4);
  EXPECT_LT(worst_height, 1e-3);
  EXPECT_LT(worst_spec, 1e-3);
}

// Grazing and normal views, a light below the horizon, zero, tiny and huge variances, full correlation:
// everything finite, weights in range, in both precisions.
TEST(MicrosurfaceFilter, ExtremeInputsStayFinite) {
  const double variances[] = {0.0, 1e-10, 1e-3, 1.0, 1e6};
  const double thetas[] = {0.0, 1e-6, 0.5, 1.4, 1.5707, 1.570796};
  int checked = 0;
  for (double var : variances)
    for (double theta : thetas)
      for (double mean : {0.0, 3.0, -50.0})
        for (double corr : {0.0, 1.0}) {
          const glm::dvec3 v(std::sin(theta), 0.0, std::cos(theta));
          const glm::dvec3 l = glm::normalize(glm::dvec3(0.3, 0.1, mean > 0 ? -0.2 : 0.9));
          const glm::dvec4 m0(0.0, var * 1e-4, mean, 0.0), m1(var + mean * mean, var, corr * var, 0.0);
          const auto check = [&](auto stats, auto vis, auto spec, auto node, auto h) {
            EXPECT_TRUE(std::isfinite(vis.lambda_v) && std::isfinite(vis.lambda_l));
            EXPECT_TRUE(vis.lit >= 0.0 && vis.lit <= 1.0) << var << " " << theta << " " << mean;
            EXPECT_TRUE(std::isfinite(spec) && spec >= 0.0) << var << " " << theta << " " << mean;
            EXPECT_TRUE(std::isfinite(node.s.x) && std::isfinite(node.s.y) && node.weight > 0.0);
            EXPECT_TRUE(std::isfinite(h));
            EXPECT_TRUE(std::isfinite(stats.h_sigma));
            ++checked;
          };
          {
            const auto s = k64::microsurface_statistics(m0, m1);
            const auto vis = k64::microsurface_visibility(s, v, l);
            check(s, vis, k64::microsurface_specular(s, glm::dvec2(0.001, 1000.0), l, v, glm::dvec4(0.0)),
                  k64::microsurface_slope_node(vis.ds, MS_SLOPE_NODES, 3, 0),
                  k64::microsurface_height_node(MS_HEIGHT_NODES - 1, s.h_mean, s.h_sigma, vis.lambda_v + vis.lambda_l));
            const auto corner3 = k64::microsurface_slope_node(vis.ds, MS_SLOPE_NODES_COSINE, 2, 0);  // the 3 x 3 grid
            EXPECT_TRUE(std::isfinite(corner3.s.x) && std::isfinite(corner3.s.y) && corner3.weight > 0.0);
          }
          {
            const auto s = k32::microsurface_statistics(glm::vec4(m0), glm::vec4(m1));
            const auto vis = k32::microsurface_visibility(s, glm::vec3(v), glm::vec3(l));
            check(
                s, vis,
                k32::microsurface_specular(s, glm::vec2(0.001f, 1000.0f), glm::vec3(l), glm::vec3(v), glm::vec4(0.0f)),
                k32::microsurface_slope_node(vis.ds, MS_SLOPE_NODES, 3, 0),
                k32::microsurface_height_node(MS_HEIGHT_NODES - 1, s.h_mean, s.h_sigma, vis.lambda_v + vis.lambda_l));
            const auto corner3 = k32::microsurface_slope_node(vis.ds, MS_SLOPE_NODES_COSINE, 2, 0);  // the 3 x 3 grid
            EXPECT_TRUE(std::isfinite(corner3.s.x) && std::isfinite(corner3.s.y) && corner3.weight > 0.0);
          }
        }
  EXPECT_EQ(checked, 2 * 5 * 6 * 3 * 2);
}

}  // namespace
}  // namespace facet
