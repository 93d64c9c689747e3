// Closed-form cross-sections of Beckmann, GGX and Kagiwada-Kalaba against brute-force quadrature over
// the sphere, their identities (odd part, endpoints, flat limit, Smith Lambda), and float against double.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "kernels/cross_section_exact.hpp"
#include "kernels/shared.hpp"
#include "sphere_quadrature.hpp"

namespace {

using namespace facet::kernels;
constexpr double kPi = std::numbers::pi;

const std::vector<double> kU = {-1.0, -0.999999, -0.7, -0.3, -1e-4, 0.0, 1e-4, 0.3, 0.7, 0.999999, 1.0};
const std::vector<double> kAlpha = {1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 1e3};
const std::vector<double> kB = {1e-6, 1e-3, 0.1, 0.5, 0.9, 0.999, 1.0 - 1e-6};

// The densities written out independently of the kernels, as functions of the polar angle.
double beckmann_D(double alpha, double th) {
  if (th >= kPi / 2) return 0.0;
  double c = std::cos(th), t = std::tan(th);
  return std::exp(-t * t / (alpha * alpha)) / (kPi * alpha * alpha * c * c * c * c);
}
double ggx_D(double alpha, double th) {
  if (th >= kPi / 2) return 0.0;
  double c = std::cos(th), s = std::sin(th);
  double q = alpha * alpha * c * c + s * s;
  return alpha * alpha / (kPi * q * q);
}
double kk_D(double b, double th) {
  double L = std::log1p(b) - std::log1p(-b);
  return b / (2.0 * kPi * L * (1.0 - b * std::cos(th)));
}

double reference_sigma(int ndf, double p, double u) {
  double horizon = p > 1.0 ? 1.0 / p : 0.0;
  if (ndf == NDF_BECKMANN)
    return facet::test::sigma_by_quadrature([&](double th) { return beckmann_D(p, th); }, u, std::min(p, 0.5), horizon);
  if (ndf == NDF_GGX)
    return facet::test::sigma_by_quadrature([&](double th) { return ggx_D(p, th); }, u, std::min(p, 0.5), horizon);
  return facet::test::sigma_by_quadrature([&](double th) { return kk_D(p, th); }, u, std::sqrt(2.0 * (1.0 - p)));
}

// Closed forms in double agree with the quadrature to 1e-12 relative to max(1, sigma) (sigma reaches
// alpha/2 = 500 for GGX at alpha = 1e3; the quadrature's own tolerance is 1e-13 relative per piece).
TEST(CrossSection, ClosedFormsMatchSphereQuadrature) {
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK}) {
    double worst = 0.0;
    for (double p : ndf == NDF_KK ? kB : kAlpha) {
      for (double u : kU) {
        double ref = reference_sigma(ndf, p, u);
        double got = f64::ndf_sigma_u(ndf, u, p);
        double scale = std::max(1.0, std::abs(ref));
        EXPECT_NEAR(got, ref, 1e-12 * scale) << "ndf " << ndf << " param " << p << " u " << u;
        worst = std::max(worst, std::abs(got - ref) / scale);
      }
    }
    std::printf("ndf %d: worst |closed form - quadrature| / max(1, sigma) = %.3g\n", ndf, worst);
  }
}

// sigma(u) - sigma(-u) = u int D m_z dm (d'Eon eq. 16), and int D m_z dm itself by quadrature
// (for the exact spherical-Gaussian sigma: sg_cross_section_test.cpp).
TEST(CrossSection, OddPartIsLinear) {
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG}) {
    for (double p : ndf == NDF_KK ? kB : kAlpha) {
      double mean = f64::ndf_mean_z(ndf, p);
      for (double u : kU) {
        double odd = f64::ndf_sigma_u(ndf, u, p) - f64::ndf_sigma_u(ndf, -u, p);
        double scale = std::max(1.0, f64::ndf_sigma_u(ndf, std::abs(u), p));  // rounding of the two sigmas
        // The fast SG sigma has the exact linear part, but where its truncated even part dips below 0
        // (u -> -1 at alpha ~ 0.1, by < 2e-5) it is clamped to 0: there only its error budget holds.
        double tolerance = ndf == NDF_SG ? 1e-4 : 1e-13 * scale;
        EXPECT_NEAR(odd, u * mean, tolerance) << "ndf " << ndf << " param " << p << " u " << u;
      }
    }
  }
  for (double b : kB) {
    double mean_ref =
        facet::test::sigma_by_quadrature([&](double th) { return kk_D(b, th); }, 1.0, std::sqrt(2.0 * (1.0 - b))) -
        facet::test::sigma_by_quadrature([&](double th) { return kk_D(b, th); }, -1.0, std::sqrt(2.0 * (1.0 - b)));
    EXPECT_NEAR(f64::ndf_kk_mean_z(b), mean_ref, 1e-13) << b;
  }
}

// sigma(1) = int D max(0, m_z) and sigma(-1) = int D max(0, -m_z): 1 and 0 for Beckmann and GGX;
// (-b - log1p(-b))/(b L) and (b - log1p(b))/(b L) for Kagiwada-Kalaba.
TEST(CrossSection, Endpoints) {
  for (double a : kAlpha) {
    for (int ndf : {NDF_BECKMANN, NDF_GGX}) {
      EXPECT_NEAR(f64::ndf_sigma_u(ndf, 1.0, a), 1.0, 1e-15);
      EXPECT_EQ(f64::ndf_sigma_u(ndf, -1.0, a), 0.0);
    }
  }
  for (double b : kB) {
    // -b - log1p(-b) = sum_{k>=2} b^k/k and b - log1p(b) = sum_{k>=2} (-1)^k b^k/k; summed as series
    // for b < 0.1, where the direct forms cancel.
    double plus = -b - std::log1p(-b), minus = b - std::log1p(b);
    if (b < 0.1) {
      plus = minus = 0.0;
      for (int k = 40; k >= 2; --k) {
        plus += std::pow(b, k) / k;
        minus += (k % 2 == 0 ? 1.0 : -1.0) * std::pow(b, k) / k;
      }
    }
    double L = std::log1p(b) - std::log1p(-b);
    EXPECT_NEAR(f64::ndf_sigma_u(NDF_KK, 1.0, b), plus / (b * L), 1e-14) << b;
    EXPECT_NEAR(f64::ndf_sigma_u(NDF_KK, -1.0, b), minus / (b * L), 1e-14) << b;
  }
}

// Flat limit: sigma -> max(0, u) as the roughness goes to 0. For Beckmann and GGX the gap is at most
// alpha/(2 sqrt(pi)) resp. alpha/2 (the value at u = 0); for the spherical Gaussian, the Beckmann gap.
TEST(CrossSection, FlatLimit) {
  for (double u : kU) {
    double flat = std::max(u, 0.0);
    EXPECT_NEAR(f64::ndf_sigma_u(NDF_BECKMANN, u, 1e-6), flat, 1e-6 / (2.0 * std::sqrt(kPi)) * 1.0000001);
    EXPECT_NEAR(f64::ndf_sigma_u(NDF_GGX, u, 1e-6), flat, 0.5e-6 * 1.0000001);
    EXPECT_NEAR(f64::ndf_sigma_u(NDF_SG, u, 1e-6), flat, 1e-6 / (2.0 * std::sqrt(kPi)) * 1.001);
  }
}

// Smith Lambda is sigma/u - 1 (for u > 0) and is computed without that cancellation: compare in
// relative terms where Lambda is not tiny, and against the asymptotic form where it is.
TEST(CrossSection, SmithLambdaConsistentWithSigma) {
  for (double a : kAlpha) {
    for (double u : {1e-4, 0.3, 0.7, 0.999999}) {
      glm::dvec3 w(std::sqrt(1 - u * u), 0.0, u);
      for (int ndf : {NDF_BECKMANN, NDF_GGX}) {
        double sigma = f64::ndf_sigma(ndf, w, a);
        double lambda =
            ndf == NDF_BECKMANN ? f64::ndf_beckmann_lambda(w, glm::dvec2(a)) : f64::ndf_ggx_lambda(w, glm::dvec2(a));
        double from_sigma = sigma / u - 1.0;
        if (from_sigma > 1e-3)
          EXPECT_NEAR(lambda, from_sigma, 1e-12 * (1.0 + from_sigma)) << ndf << " " << a << " " << u;
        else
          EXPECT_NEAR(lambda, from_sigma, 1e-15);
        EXPECT_GE(lambda, 0.0);
      }
    }
  }
  // Beckmann deep in the mirror regime: Lambda ~ exp(-a^2)/(4 a^3 sqrt(pi)) (1 - 3/(2a^2)), a = u/(alpha s) = 10.
  double a = 10.0;
  double u = 1.0 / std::sqrt(1.0 + 1.0 / (0.01 * 0.01 * a * a));
  glm::dvec3 w(std::sqrt(1 - u * u), 0.0, u);
  double asym = std::exp(-a * a) / (4.0 * a * a * a * std::sqrt(kPi)) * (1.0 - 1.5 / (a * a));
  EXPECT_NEAR(f64::ndf_beckmann_lambda(w, glm::dvec2(0.01)) / asym, 1.0, 5e-4);  // next term 15/(4a^4)
}

// Anisotropic roughness: sigma(w) depends on alpha_x, alpha_y only through the projected alpha_w, so
// it must equal the isotropic value with alpha = alpha_w / sin(theta); checked against quadrature of
// the anisotropic D over the sphere in (theta, phi).
TEST(CrossSection, AnisotropicMatchesQuadrature) {
  glm::dvec2 alpha(0.2, 0.6);
  glm::dvec3 w = glm::normalize(glm::dvec3(0.5, 0.7, 0.3));
  for (int ndf : {NDF_BECKMANN, NDF_GGX}) {
    auto integrand_phi = [&](double th) {
      auto f = [&](double ph) {
        glm::dvec3 m(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        double D = ndf == NDF_BECKMANN ? f64::ndf_beckmann_D(m, alpha) : f64::ndf_ggx_D(m, alpha);
        return D * std::max(0.0, glm::dot(m, w)) * std::sin(th);
      };
      return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, 0.0, 2 * kPi, 8, 1e-11);
    };
    double ref = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand_phi, 0.0, kPi / 2, 8, 1e-10);
    double got = ndf == NDF_BECKMANN ? f64::ndf_beckmann_sigma(w, alpha) : f64::ndf_ggx_sigma(w, alpha);
    EXPECT_NEAR(got, ref, 1e-9) << ndf;
  }
}

// The float twin (what the GPU runs) against the double one, over extreme parameters: finite, >= 0,
// and within 3e-6 of max(1, sigma) (a few ulp of float through erfcx/log/exp; sigma reaches 500).
TEST(CrossSection, FloatTwinMatchesDoubleEverywhere) {
  double worst[4] = {0, 0, 0, 0};
  for (int ndf : {NDF_BECKMANN, NDF_GGX, NDF_KK, NDF_SG}) {
    std::vector<double> params = ndf == NDF_KK ? kB : kAlpha;
    for (double p : params) {
      for (int i = 0; i <= 400; ++i) {
        double u = -1.0 + 2.0 * i / 400.0;
        float got = f32::ndf_sigma_u(ndf, static_cast<float>(u), static_cast<float>(p));
        double ref = f64::ndf_sigma_u(ndf, static_cast<double>(static_cast<float>(u)),
                                      static_cast<double>(static_cast<float>(p)));
        ASSERT_TRUE(std::isfinite(got) && got >= 0.0f) << ndf << " " << p << " " << u;
        worst[ndf] = std::max(worst[ndf], std::abs(got - ref) / std::max(1.0, ref));
      }
    }
    EXPECT_LT(worst[ndf], 3e-6) << "ndf " << ndf;
    std::printf("ndf %d: worst |f32 - f64| / max(1, sigma) = %.3g\n", ndf, worst[ndf]);
  }
}

TEST(CrossSection, CliEntryPoint) {
  EXPECT_EQ(cross_section(NDF_GGX, 0.3, 0.4, true), f64::ndf_sigma_u(NDF_GGX, 0.4, 0.3));
  EXPECT_NEAR(cross_section(NDF_SG, 0.3, 0.4, false), cross_section(NDF_SG, 0.3, 0.4, true), 1e-4);
}

}  // namespace
