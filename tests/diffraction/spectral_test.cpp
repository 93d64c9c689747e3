// The compiled-in CIE tables against the published checks (data/cie: CIE 1931 2° observer, ISO/CIE 11664-1; D65,
// ISO/CIE 11664-2) and the wavelength integration against the 1 nm sums.
#include <gtest/gtest.h>

#include <cmath>

#include "diffraction/cie_tables.hpp"
#include "diffraction/spectral_integration.hpp"
#include "diffraction_cases.hpp"
#include "kernels/shared.hpp"

namespace facet {
namespace {

using namespace diffraction;

glm::dvec2 chromaticity(glm::dvec3 xyz) { return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z); }

TEST(Spectral, CieTablesHoldThePublishedValues) {
  EXPECT_DOUBLE_EQ(cie_cmf(555.0).y, 1.0);
  EXPECT_DOUBLE_EQ(cie_cmf(600.0).x, 1.0622);
  EXPECT_DOUBLE_EQ(cie_cmf(450.0).z, 1.77211);
  EXPECT_DOUBLE_EQ(cie_d65(560.0), 100.0);
  double y_sum = 0.0;
  for (int l = 360; l <= 830; ++l) y_sum += cie_cmf(l).y;
  EXPECT_NEAR(y_sum, 106.857, 5e-4);
  // Between entries: the Catmull-Rom cubic, (-p0 + 9 p1 + 9 p2 - p3) / 16 at the midpoint; outside: zero.
  EXPECT_NEAR(cie_d65(562.5), (-cie_d65(555.0) + 9 * cie_d65(560.0) + 9 * cie_d65(565.0) - cie_d65(570.0)) / 16, 1e-12);
  EXPECT_EQ(cie_cmf(300.0), glm::dvec3(0.0));
  EXPECT_EQ(cie_d65(900.0), 0.0);
}

// D65 through the 1931 observer is (0.3127, 0.3290) (4 decimals), and since the sRGB matrix is
// built on exactly that white, a spectrally flat surface under D65 comes out as linear sRGB
// (1, 1, 1) to the same 4-decimal agreement (1e-3). Equal-energy light gives x = y = 1/3 (to 1e-3).
TEST(Spectral, WhitePointsAndSrgbWhite) {
  const auto d65 = wavelength_samples(1.0, Illuminant::D65);
  const glm::dvec2 xy = chromaticity(integrate_xyz(d65, [](double) { return 1.0; }));
  EXPECT_NEAR(xy.x, 0.3127, 5e-5);
  EXPECT_NEAR(xy.y, 0.3290, 5e-5);
  const glm::dvec3 rgb = integrate_linear_srgb(d65, [](double) { return 1.0; });
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 1e-3) << c;
  const glm::dvec2 e = chromaticity(integrate_xyz(wavelength_samples(1.0, Illuminant::E), [](double) { return 1.0; }));
  EXPECT_NEAR(e.x, 1.0 / 3.0, 1e-3);
  EXPECT_NEAR(e.y, 1.0 / 3.0, 1e-3);
  // The matrix maps the sRGB primaries' white Y = 1 exactly to (1, 1, 1) (rational derivation).
  const glm::dvec3 w =
      kernels::f64::spectral_xyz_to_linear_srgb({0.3127 / 0.3290, 1.0, (1 - 0.3127 - 0.3290) / 0.3290});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], 1.0, 1e-14);
}

// The spacing chosen from a tolerance keeps the white within it, and a smooth reflectance spectrum
// (not what the spacing was chosen on) integrates to within 5 times the same tolerance (measured:
// 4.4 at 1e-4; the white is only a proxy for smooth spectra).
TEST(Spectral, ObserverSpacingMeetsItsTolerance) {
  const auto fine = wavelength_samples(1.0);
  auto smooth = [](double l) { return 0.5 + 0.4 * std::sin(l / 37.0); };
  const glm::dvec3 reference = integrate_xyz(fine, smooth);
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const double h = observer_spacing(tol);
    const auto s = wavelength_samples(h);
    const glm::dvec3 white =
        integrate_xyz(s, [](double) { return 1.0; }) - integrate_xyz(fine, [](double) { return 1.0; });
    EXPECT_LE(std::max({std::abs(white.x), std::abs(white.y), std::abs(white.z)}), tol) << h;
    const glm::dvec3 d = integrate_xyz(s, smooth) - reference;
    EXPECT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), 5 * tol) << "spacing " << h;
  }
}

// The narrowest peak a grating's BRDF can have in wavelength (standard deviation s at |u| = 2) is
// integrated at peak_spacing with relative error below the tolerance, wherever it sits on the grid.
TEST(Spectral, PeakSpacingResolvesTheNarrowestPeak) {
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":2500,"amplitude_nm":50,"size_um":20,"samples":64})");
  const auto t = build_spectral_tables(g);
  const double lambda_min = 380.0, tol = 1e-3;
  const double k_max = 2 * test::kPi / lambda_min;
  const double s = lambda_min / (std::sqrt(2.0) * k_max * t.sigma_nm * 2.0);
  const double h = peak_spacing(t, lambda_min, tol);
  const auto coarse = wavelength_samples(h), fine = wavelength_samples(s / 20);
  for (double centre : {450.0, 451.1 + 0.37 * h, 555.0 + 0.5 * h, 610.3}) {
    auto peak = [&](double l) { return std::exp(-0.5 * (l - centre) * (l - centre) / (s * s)); };
    const glm::dvec3 a = integrate_xyz(coarse, peak), b = integrate_xyz(fine, peak);
    EXPECT_NEAR(a.y / b.y, 1.0, tol) << centre << " spacing " << h << " s " << s;
  }
  // The combined choice is at least as fine as either criterion.
  const auto both = diffraction_wavelength_samples(t, tol);
  const double spacing = both.lambda_nm[1] - both.lambda_nm[0];
  EXPECT_LE(spacing, std::min(observer_spacing(tol), peak_spacing(t, kCieLambdaMinNm, tol)) + 1e-12);
}

}  // namespace
}  // namespace facet
