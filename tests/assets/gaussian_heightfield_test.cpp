// Gaussian random height fields (renderer/assets/gaussian_heightfield.hpp): the slope covariance
// derivation, the normalisation, ensemble statistics against the ACF, determinism, validation.
#include "assets/gaussian_heightfield.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include "assets/slope_statistics.hpp"
#include "assets/white_noise.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace facet::assets {
namespace {

GaussianHeightfieldParams anisotropic() {
  GaussianHeightfieldParams p;
  p.width = 128;
  p.height = 96;
  p.texel_size = 0.5;
  p.sigma_h = 0.3;
  p.corr_x = 5.0;                                                 // 10 texels
  p.corr_y = 2.5;                                                 // 5 texels
  p.angle_deg = std::atan2(3.0, 4.0) * 180.0 / std::numbers::pi;  // ℓ_x axis along (4, 3)
  p.seed = 42;
  return p;
}

// The same 24 fields (seeds 1000...1023) of anisotropic(), generated once for all ensemble tests.
const std::vector<ScalarField>& ensemble() {
  static const std::vector<ScalarField> fields = [] {
    std::vector<ScalarField> result;
    GaussianHeightfieldParams p = anisotropic();
    for (int s = 0; s < 24; ++s) {
      p.seed = 1000 + s;
      result.push_back(generate_gaussian_heightfield(p));
    }
    return result;
  }();
  return fields;
}

struct Moments {
  double mean = 0.0, std_error = 0.0;
};
// Mean over the ensemble of `statistic(field)` and its standard error estimated from the spread.
template <class Statistic>
Moments over_ensemble(Statistic statistic) {
  std::vector<double> values;
  for (const ScalarField& f : ensemble()) values.push_back(statistic(f));
  double n = static_cast<double>(values.size());
  Moments m;
  for (double v : values) m.mean += v;
  m.mean /= n;
  double var = 0.0;
  for (double v : values) var += (v - m.mean) * (v - m.mean);
  m.std_error = std::sqrt(var / (n - 1) / n);
  return m;
}

TEST(GaussianWhiteNoise, IsStandardNormalAndReproducible) {
  GaussianWhiteNoise noise(7), same(7), other(8);
  const int n = 1 << 20;
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  bool identical = true, differs = false;
  for (int k = 0; k < n; ++k) {
    double x = noise.next(), y = same.next(), z = other.next();
    identical = identical && x == y;
    differs = differs || x != z;
    sum += x;
    sum2 += x * x;
    sum4 += x * x * x * x;
  }
  EXPECT_TRUE(identical);
  EXPECT_TRUE(differs);
  // Standard errors for n = 2^20 samples: mean 1/√n = 1e-3, variance √(2/n) = 1.4e-3, fourth
  // moment √(96/n) = 9.6e-3; tolerances are 5 of them.
  EXPECT_NEAR(sum / n, 0.0, 5e-3);
  EXPECT_NEAR(sum2 / n, 1.0, 7e-3);
  EXPECT_NEAR(sum4 / n, 3.0, 5e-2);
}

TEST(GaussianHeightfield, SlopeCovarianceIsMinusTheAcfHessian) {
  // eq. A3 against central second differences of C itself; step ℓ/1000: truncation
  // ~(h²/12)·C'''' ~ 1e-7 relative, rounding ~1e-16/1e-6 = 1e-10.
  GaussianHeightfieldParams p = anisotropic();
  SlopeCovariance s = analytic_slope_covariance(p);
  double h = 1e-3 * p.corr_y, c0 = gaussian_acf(p, 0, 0);
  double cxx = (gaussian_acf(p, h, 0) - 2 * c0 + gaussian_acf(p, -h, 0)) / (h * h);
  double cyy = (gaussian_acf(p, 0, h) - 2 * c0 + gaussian_acf(p, 0, -h)) / (h * h);
  double cxy =
      (gaussian_acf(p, h, h) - gaussian_acf(p, h, -h) - gaussian_acf(p, -h, h) + gaussian_acf(p, -h, -h)) / (4 * h * h);
  EXPECT_NEAR(s.var_x, -cxx, 1e-6 * s.var_x);
  EXPECT_NEAR(s.var_y, -cyy, 1e-6 * s.var_y);
  EXPECT_NEAR(s.cov_xy, -cxy, 1e-6 * s.var_x);
  // The principal slope variances are 2σ²/ℓ_x² and 2σ²/ℓ_y² (eigenvalues of Σ_s).
  double trace = s.var_x + s.var_y, det = s.var_x * s.var_y - s.cov_xy * s.cov_xy;
  double sigma2 = p.sigma_h * p.sigma_h;
  EXPECT_NEAR(trace, 2 * sigma2 / (p.corr_x * p.corr_x) + 2 * sigma2 / (p.corr_y * p.corr_y), 1e-15);
  EXPECT_NEAR(det, 4 * sigma2 * sigma2 / (p.corr_x * p.corr_x * p.corr_y * p.corr_y), 1e-15);
  // The short axis (steep slopes) lies along (−3, 4): slopes along x and y correlate negatively.
  EXPECT_LT(s.cov_xy, 0.0);
}

TEST(GaussianHeightfield, SampleMeanIsZeroAndSampleStdIsSigma) {
  GaussianHeightfieldParams p = anisotropic();
  ScalarField f = generate_gaussian_heightfield(p);
  ASSERT_EQ(f.values.size(), 128u * 96u);
  double sum = 0.0, sum2 = 0.0;
  for (double h : f.values) {
    ASSERT_TRUE(std::isfinite(h));
    sum += h;
    sum2 += h * h;
  }
  double n = static_cast<double>(f.values.size());
  EXPECT_NEAR(sum / n, 0.0, 1e-15);
  EXPECT_NEAR(std::sqrt(sum2 / n), p.sigma_h, 1e-14);
  p.sigma_h = 0.0;  // a flat field is allowed
  for (double h : generate_gaussian_heightfield(p).values) EXPECT_EQ(h, 0.0);
}

// Ensemble autocovariance at grid lag (lx, ly), normalised by the sample variance.
double sample_correlation(const ScalarField& f, int lx, int ly) {
  double sum = 0.0, sum2 = 0.0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      sum += f.at(x, y) * f.wrapped(x + lx, y + ly);
      sum2 += f.at(x, y) * f.at(x, y);
    }
  return sum / sum2;
}

TEST(GaussianHeightfield, CorrelationFollowsTheOrientedGaussianAcf) {
  // With the ℓ_x axis along (4, 3) and ℓ_x = 10 texels, lag (8, 6) texels lies one ℓ_x along the
  // long axis and lag (−3, 4) one ℓ_y = 5 texels along the short axis: both have ρ = e^−1 (checked
  // on C below). The mirrored lags (8, −6) and (3, 4) are off the axes and tell the orientation
  // from its mirror image.
  GaussianHeightfieldParams p = anisotropic();
  struct Lag {
    int x, y;
  };
  for (Lag lag : {Lag{8, 6}, Lag{-3, 4}, Lag{8, -6}, Lag{3, 4}, Lag{1, 0}, Lag{0, 1}}) {
    double expected = gaussian_acf(p, lag.x * p.texel_size, lag.y * p.texel_size) / gaussian_acf(p, 0, 0);
    Moments m = over_ensemble([&](const ScalarField& f) { return sample_correlation(f, lag.x, lag.y); });
    // 5 standard errors (estimated from the spread over seeds).
    EXPECT_NEAR(m.mean, expected, 5 * m.std_error) << lag.x << "," << lag.y;
    EXPECT_LT(m.std_error, 0.02);  // the test can tell e^−1 from its neighbours
  }
  EXPECT_NEAR(gaussian_acf(p, 8 * p.texel_size, 6 * p.texel_size), p.sigma_h * p.sigma_h * std::exp(-1.0), 1e-15);
  EXPECT_NEAR(gaussian_acf(p, -3 * p.texel_size, 4 * p.texel_size), p.sigma_h * p.sigma_h * std::exp(-1.0), 1e-15);
}

TEST(GaussianHeightfield, FiniteDifferenceSlopesMatchTheAcf) {
  // Forward differences of the grid have E[s_x²] = 2(C(0) − C(Δ, 0))/Δ², and
  // E[s_x s_y] = (C(0) − C(Δ, 0) − C(0, Δ) + C(−Δ, Δ))/Δ² (eq. A5), which tend to Σ_s (eq. A3) as
  // Δ/ℓ → 0 with relative bias ≈ −Δ² A/2. The field is normalised to sample variance σ_h², so
  // the ratio to the sample variance is what is compared.
  GaussianHeightfieldParams p = anisotropic();
  double d = p.texel_size, c0 = gaussian_acf(p, 0, 0);
  double ex = 2 * (c0 - gaussian_acf(p, d, 0)) / (d * d);
  double ey = 2 * (c0 - gaussian_acf(p, 0, d)) / (d * d);
  double exy = (c0 - gaussian_acf(p, d, 0) - gaussian_acf(p, 0, d) + gaussian_acf(p, -d, d)) / (d * d);
  Moments mx = over_ensemble([&](const ScalarField& f) { return forward_difference_slopes(f, d).var_x; });
  Moments my = over_ensemble([&](const ScalarField& f) { return forward_difference_slopes(f, d).var_y; });
  Moments mxy = over_ensemble([&](const ScalarField& f) { return forward_difference_slopes(f, d).cov_xy; });
  EXPECT_NEAR(mx.mean, ex, 5 * mx.std_error);
  EXPECT_NEAR(my.mean, ey, 5 * my.std_error);
  EXPECT_NEAR(mxy.mean, exy, 5 * mxy.std_error);
  EXPECT_LT(mx.std_error, 0.05 * ex);  // the comparison resolves 5%

  // Discretisation: the finite-difference moments approach Σ_s as Δ → 0, error O(Δ²).
  SlopeCovariance s = analytic_slope_covariance(p);
  for (double step : {0.1, 0.01, 0.001}) {
    double h = step * p.corr_y;
    double fx = 2 * (c0 - gaussian_acf(p, h, 0)) / (h * h);
    double fxy = (c0 - gaussian_acf(p, h, 0) - gaussian_acf(p, 0, h) + gaussian_acf(p, -h, h)) / (h * h);
    EXPECT_NEAR(fx / s.var_x, 1.0, 2 * step * step * p.corr_y * p.corr_y * s.var_x / (p.sigma_h * p.sigma_h) + 1e-9);
    EXPECT_NEAR(fxy / s.cov_xy, 1.0, 20 * step * (1 + 1e-9));
  }
}

TEST(GaussianHeightfield, FieldTilesSeamlessly) {
  // Across the wrap (last column -> first, last row -> first) the differences have the same
  // statistics as inside: the mean square over the seam rows is compared with the interior's.
  auto seam_minus_interior = [&](const ScalarField& f) {
    double seam = 0.0, inner = 0.0;
    for (int y = 0; y < f.height; ++y) {
      seam += std::pow(f.at(0, y) - f.at(f.width - 1, y), 2);
      inner += std::pow(f.at(f.width / 2, y) - f.at(f.width / 2 - 1, y), 2);
    }
    return (seam - inner) / f.height;
  };
  Moments m = over_ensemble(seam_minus_interior);
  EXPECT_NEAR(m.mean, 0.0, 5 * m.std_error);
}

TEST(GaussianHeightfield, SameSeedSameBytesOtherSeedOtherField) {
  GaussianHeightfieldParams p = anisotropic();
  ScalarField a = generate_gaussian_heightfield(p), b = generate_gaussian_heightfield(p);
  EXPECT_EQ(a.values, b.values);
  p.seed += 1;
  ScalarField c = generate_gaussian_heightfield(p);
  int equal = 0;
  for (std::size_t k = 0; k < a.values.size(); ++k) equal += a.values[k] == c.values[k];
  EXPECT_EQ(equal, 0);

  const test::TempDir dir;
  p.seed -= 1;
  write_scalar_field_exr(dir / "a.exr", a, heightfield_metadata(p, a));
  write_scalar_field_exr(dir / "b.exr", generate_gaussian_heightfield(p), heightfield_metadata(p, b));
  auto bytes = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(dir / "a.exr"), bytes(dir / "b.exr"));
  ExrMetadata metadata;
  ScalarField back = read_scalar_field_exr(dir / "a.exr", &metadata);
  ASSERT_EQ(back.width, 128);
  ASSERT_EQ(back.height, 96);
  for (std::size_t k = 0; k < a.values.size(); ++k)  // float32 in the file: exact float rounding
    ASSERT_EQ(back.values[k], static_cast<double>(static_cast<float>(a.values[k])));
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:generator")), "gaussian_heightfield");
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:seed")), "42");
  EXPECT_DOUBLE_EQ(std::get<double>(metadata.at("facet:slope_var_x")), analytic_slope_covariance(p).var_x);
  EXPECT_DOUBLE_EQ(std::get<double>(metadata.at("facet:corr_y")), 2.5);
}

TEST(GaussianHeightfield, RejectsBadParameters) {
  auto with = [](auto change) {
    GaussianHeightfieldParams p = anisotropic();
    change(p);
    return p;
  };
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.width = 1; })), Error);
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.texel_size = 0; })), Error);
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.sigma_h = -1; })), Error);
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.corr_x = 0; })), Error);
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.corr_y = NAN; })), Error);
  EXPECT_THROW(generate_gaussian_heightfield(with([](auto& p) { p.angle_deg = INFINITY; })), Error);
  // ℓ_x = period/4 along x is accepted; a little more is not.
  EXPECT_NO_THROW(validate(with([](auto& p) {
    p.angle_deg = 0;
    p.corr_x = 128 * 0.5 / 4;
  })));
  EXPECT_THROW(validate(with([](auto& p) {
                 p.angle_deg = 0;
                 p.corr_x = 128 * 0.5 / 3.9;
               })),
               Error);
}

}  // namespace
}  // namespace facet::assets
