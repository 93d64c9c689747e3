// The single-scattering microflake half-space BRDF (shaders/lib/microflake_brdf.glsl): reciprocity,
// energy (albedo <= 1), its closed forms in the isotropic (Lommel-Seeliger) and Beckmann/GGX
// (height-correlated Smith) cases, the mirror limit, and the albedo computed from the BRDF against
// the albedo of the physical process it was derived from (Monte Carlo over visible normals).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "kernels/shared.hpp"

namespace microflake_brdf_test {

using namespace facet::kernels;
constexpr double kPi = std::numbers::pi;

glm::dvec3 direction(double z, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

struct Material {
  int ndf;
  double param;
  double width;  // angular width of D around +z, for quadrature breakpoints
};

const std::vector<Material> kMaterials = {
    {NDF_BECKMANN, 0.05, 0.05}, {NDF_BECKMANN, 0.5, 0.5}, {NDF_GGX, 0.05, 0.05},
    {NDF_GGX, 0.5, 0.5},        {NDF_KK, 0.3, 1.0},       {NDF_KK, 0.999, 0.05},
    {NDF_SG, 0.05, 0.05},       {NDF_SG, 0.5, 0.5},       {NDF_SG, 3.0, 1.0},
};

// Directional albedo A(wi) = int f(wi, wo) mu_o dwo over the hemisphere of wo in (theta_o, phi_o),
// which keeps the horizon (f = 0 below it) on a cell edge; both angles are split at multiples of the
// specular lobe's width 2w around the mirror direction, with a 24-point Gauss rule per piece.
std::vector<double> split(double lo, double hi, double centre, double step) {
  std::vector<double> b = {lo, hi};
  for (double k : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0}) {
    for (double x : {centre - k * step, centre + k * step}) {
      if (x > lo && x < hi) b.push_back(x);
    }
  }
  std::sort(b.begin(), b.end());
  return b;
}

double albedo_by_quadrature(const Material& mat, glm::dvec3 wi) {
  double theta_i = std::acos(wi.z);
  double phi_r = std::atan2(wi.y, wi.x) + kPi;
  double lobe = 2.0 * mat.width;
  std::vector<double> thetas = split(0.0, kPi / 2, theta_i, lobe);
  std::vector<double> phis = split(phi_r - kPi, phi_r + kPi, phi_r, lobe / std::max(std::sin(theta_i), lobe));
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < thetas.size(); ++i) {
    auto over_theta = [&](double th) {
      auto over_phi = [&](double ph) {
        glm::dvec3 wo(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        return f64::microflake_brdf(mat.ndf, mat.param, wi, wo) * wo.z * std::sin(th);
      };
      double s = 0.0;
      for (std::size_t j = 0; j + 1 < phis.size(); ++j)
        s += boost::math::quadrature::gauss<double, 24>::integrate(over_phi, phis[j], phis[j + 1]);
      return s;
    };
    sum += boost::math::quadrature::gauss<double, 24>::integrate(over_theta, thetas[i], thetas[i + 1]);
  }
  return sum;
}

TEST(MicroflakeBrdf, Reciprocity) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const Material& mat : kMaterials) {
    for (int n = 0; n < 200; ++n) {
      glm::dvec3 wi = direction(uniform(rng), 2 * kPi * uniform(rng));
      glm::dvec3 wo = direction(uniform(rng), 2 * kPi * uniform(rng));
      double a = f64::microflake_brdf(mat.ndf, mat.param, wi, wo);
      double b = f64::microflake_brdf(mat.ndf, mat.param, wo, wi);
      EXPECT_NEAR(a, b, 1e-13 * std::max(1.0, a)) << mat.ndf << " " << mat.param;
      float af = f32::microflake_brdf(mat.ndf, float(mat.param), glm::vec3(wi), glm::vec3(wo));
      EXPECT_TRUE(std::isfinite(af) && af >= 0.0f);
    }
  }
}

// Isotropic flakes (KK b -> 0, SG alpha -> inf): sigma = 1/4 in every direction, the phase function is
// 1/(4 pi), and single scattering is Lommel-Seeliger, f = 1/(4 pi (mu_i + mu_o)), with albedo
// A(mu) = (1 - mu log((1 + mu)/mu))/2 (both closed forms written here).
TEST(MicroflakeBrdf, IsotropicLimitIsLommelSeeliger) {
  for (Material mat : {Material{NDF_KK, 1e-6, 1.0}, Material{NDF_SG, 1e3, 1.0}}) {
    for (double mu_i : {0.05, 0.3, 0.7, 1.0}) {
      glm::dvec3 wi = direction(mu_i, 0.4);
      for (double mu_o : {0.01, 0.5, 1.0}) {
        glm::dvec3 wo = direction(mu_o, 2.0);
        EXPECT_NEAR(f64::microflake_brdf(mat.ndf, mat.param, wi, wo), 1.0 / (4 * kPi * (mu_i + mu_o)),
                    2e-7 / (mu_i + mu_o));
      }
      double closed = 0.5 * (1.0 - mu_i * std::log((1.0 + mu_i) / mu_i));
      EXPECT_NEAR(albedo_by_quadrature(mat, wi), closed, 1e-6) << mat.ndf << " mu_i " << mu_i;
    }
  }
}

// Beckmann and GGX: the BRDF equals the height-correlated Smith microfacet BRDF
// D(h) / (4 mu_i mu_o (1 + Lambda_i + Lambda_o)).
TEST(MicroflakeBrdf, BeckmannAndGgxAreHeightCorrelatedSmith) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int ndf : {NDF_BECKMANN, NDF_GGX}) {
    for (double a : {0.01, 0.3, 1.0}) {
      glm::dvec2 alpha(a);
      for (int n = 0; n < 100; ++n) {
        glm::dvec3 wi = direction(uniform(rng), 2 * kPi * uniform(rng));
        glm::dvec3 wo = direction(uniform(rng), 2 * kPi * uniform(rng));
        glm::dvec3 h = glm::normalize(wi + wo);
        double li = ndf == NDF_BECKMANN ? f64::ndf_beckmann_lambda(wi, alpha) : f64::ndf_ggx_lambda(wi, alpha);
        double lo = ndf == NDF_BECKMANN ? f64::ndf_beckmann_lambda(wo, alpha) : f64::ndf_ggx_lambda(wo, alpha);
        double smith = f64::ndf_D(ndf, h, a) / (4.0 * wi.z * wo.z * (1.0 + li + lo));
        EXPECT_NEAR(f64::microflake_brdf(ndf, a, wi, wo), smith, 1e-12 * std::max(1.0, smith));
      }
    }
  }
}

// White furnace: the single-scattering albedo is <= 1 for every material and direction (with the
// quadrature's 1e-6 tolerance), and tends to 1 for a mirror (Beckmann/GGX alpha = 1e-3 at normal
// incidence lose only O(alpha) to masking).
TEST(MicroflakeBrdf, AlbedoAtMostOne) {
  for (const Material& mat : kMaterials) {
    for (double mu_i : {0.02, 0.2, 0.5, 0.9, 1.0}) {
      double albedo = albedo_by_quadrature(mat, direction(mu_i, 0.3));
      EXPECT_LE(albedo, 1.0 + 1e-6) << mat.ndf << " " << mat.param << " " << mu_i;
      EXPECT_GT(albedo, 0.0);
      std::printf("ndf %d param %g mu_i %.2f: albedo %.6f\n", mat.ndf, mat.param, mu_i, albedo);
    }
  }
  for (int ndf : {NDF_BECKMANN, NDF_GGX}) {
    double albedo = albedo_by_quadrature(Material{ndf, 1e-3, 1e-3}, direction(1.0, 0.0));
    EXPECT_NEAR(albedo, 1.0, 2e-3) << ndf;
  }
}

// The process the BRDF was derived from: light enters along -wi, is extinguished with coefficient
// sigma(wi)/mu_i per unit depth, is reflected by a visible normal m into wo = reflect(wi, m) and
// escapes from depth d with probability exp(-sigma(-wo) d / mu_o) (0 if wo points down). Averaging
// the escape probability over the exponential depth gives sigma_i mu_o/(sigma_i mu_o + sigma(-wo) mu_i);
// its mean over visible normals (sampled) must equal the albedo integrated from the BRDF.
TEST(MicroflakeBrdf, AlbedoMatchesScatteringProcess) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int samples = 100000;
  for (const Material& mat : kMaterials) {
    for (double mu_i : {0.2, 0.8}) {
      glm::dvec3 wi = direction(mu_i, 0.3);
      double sigma_i = f64::ndf_sigma(mat.ndf, wi, mat.param);
      double sum = 0.0, sum2 = 0.0;
      for (int n = 0; n < samples; ++n) {
        glm::dvec3 m = f64::ndf_sample_visible(mat.ndf, wi, mat.param, glm::dvec2(uniform(rng), uniform(rng)));
        glm::dvec3 wo = 2.0 * glm::dot(m, wi) * m - wi;
        double escape = 0.0;
        if (wo.z > 0.0) {
          double sigma_down = f64::ndf_sigma(mat.ndf, -wo, mat.param);
          escape = sigma_i * wo.z / (sigma_i * wo.z + sigma_down * mu_i);
        }
        sum += escape;
        sum2 += escape * escape;
      }
      double mean = sum / samples;
      double stderr_mean = std::sqrt(std::max(sum2 / samples - mean * mean, 0.0) / samples);
      double albedo = albedo_by_quadrature(mat, wi);
      EXPECT_NEAR(mean, albedo, 5.0 * stderr_mean + 1e-5) << mat.ndf << " " << mat.param << " mu_i " << mu_i;
    }
  }
}

}  // namespace microflake_brdf_test
