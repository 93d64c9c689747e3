// Order-restricted wavelengths (docs/diffraction_fast_paths.md) against the per-wavelength path on
// sinusoidal, rectangular and crossed gratings (colours, peak positions, cost), the pieces of the
// kernel against brute force (patch periods, intervals, partition of unity), the GPU against the
// double twin, and the fallback of a height field that is not periodic.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "diffraction/chebyshev_transform.hpp"
#include "diffraction/cie_tables.hpp"
#include "diffraction/order_wavelengths.hpp"
#include "diffraction_cases.hpp"
#include "order_cases.hpp"
#include "orders_probe.hpp"
#include "scene/grating/grating_patterns.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace orders_test {

using namespace diffraction;
using namespace order_cases;
using test::direction;
using test::kPi;
namespace k64 = kernels::f64;

glm::dvec3 spectral(const Case& c, const WavelengthSamples& s, const glm::dvec3& wi, const glm::dvec3& wr) {
  return integrate_linear_srgb(s, [&](double l) { return evaluate_taylor(c.tables, {wi, wr, l}).brdf; });
}

TEST(Orders, PatchRepeatsAreTheGratingsPeriods) {
  auto repeats = [](const char* json) { return patch_repeats(test::grating(json)); };
  EXPECT_EQ(repeats(kSinusoidJson).x, 4);
  EXPECT_EQ(repeats(kSinusoidJson).y, 64);  // constant along y
  EXPECT_EQ(repeats(kRectangularJson).x, 5);
  EXPECT_EQ(repeats(kCrossedJson).x, 4);
  EXPECT_EQ(repeats(kCrossedJson).y, 5);
  // Fingers: ridges of period 1000 nm along x, rows shifted every 1000 nm along y (period 2000 nm).
  const auto fingers = repeats(R"({"type":"fingers","period_nm":1000,"amplitude_nm":80,"size_um":4,"samples":64,)"
                               R"("finger_length_nm":1000})");
  EXPECT_EQ(fingers.x, 4);
  EXPECT_EQ(fingers.y, 2);
}

// A sampled sinusoid of n periods over M samples, sin(2 pi n i / M), is unchanged by a shift of s
// samples exactly when n s / M is whole (for 0 < n < M / 2), i.e. s a multiple of M / gcd(M, n): the
// patch repeats gcd(M, n) times, n when each period spans a whole number of samples and fewer
// otherwise (M = 96, n = 10: 9.6 samples per period, 2 repeats). Crossed fields, each axis on its own.
TEST(Orders, PatchRepeatsOfPeriodsThatAreNotWholeSamples) {
  for (int M : {60, 96, 120})
    for (int nx : {4, 5, 7, 10, 12})
      for (int ny : {3, 8, 9}) {
        Grating g;
        g.samples = M;
        g.sample_nm = 100.0;
        g.height_nm = crossed_heights({M, g.sample_nm}, 100.0 * M / nx, 100.0 * M / ny, 80.0);
        const PatchRepeats r = patch_repeats(g);
        EXPECT_EQ(r.x, std::gcd(M, nx)) << M << " " << nx;
        EXPECT_EQ(r.y, std::gcd(M, ny)) << M << " " << ny;
      }
}

// Sum over the orders within the reach's radius of k (u, v) (those whose intervals can hold the
// wavelength) of their shares is 1 (F.8), for any (u, v) and wavelength.
TEST(Orders, SharesAreAPartitionOfUnity) {
  const Case c = make_case(kCrossedJson);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uv(-1.5, 1.5), lambda(360.0, 830.0);
  for (int q = 0; q < 200; ++q) {
    const glm::dvec2 p(uv(rng), uv(rng));
    const double l = lambda(rng);
    const glm::dvec2 position = 2 * kPi / l * p / c.plan.lattice.frequency;
    const glm::ivec2 nearest = glm::ivec2(glm::floor(position + 0.5));
    const glm::ivec2 radius = glm::ivec2(glm::floor(c.plan.lattice.reach / c.plan.lattice.frequency + 0.5));
    double total = 0.0;
    for (int dy = -radius.y; dy <= radius.y; ++dy)
      for (int dx = -radius.x; dx <= radius.x; ++dx)
        total += k64::diffraction_order_share(c.plan.lattice, p, l, nearest + glm::ivec2(dx, dy));
    EXPECT_NEAR(total, 1.0, 1e-12) << q;
  }
}

// F.12: a patch that holds P periods has non-zero DFT coefficients only at multiples of P, so the
// BRDF summed over the window's lattice bins alone (bin_stride = the repeats, as the orders path
// does) equals the sum over every bin of the window, up to the float-free roundoff of the tables'
// FFT (1e-9 of the largest value over random views and wavelengths, double). The stride does skip
// bins: with it the window visits at most ceil((2r + 1) / P) per axis.
TEST(Orders, LatticeBinsCarryTheWholeWindowSum) {
  // Besides the three gratings (windows of one bin): scenes/diffraction_plate.json's (r = 2, P = 80
  // along y: the window's 5 rows shrink to one; along x 16 samples per period, P = 5: one column)
  // and a window narrow enough for two lattice bins per axis (r = 2, P = 4).
  const char* plate =
      R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":100,"size_um":8,"samples":80,"coherence_um":3.2})";
  const char* narrow =
      R"({"type":"crossed","period_nm":[500,500],"amplitude_nm":40,"size_um":2,"samples":64,"coherence_um":0.5})";
  int most_lattice_bins = 0;
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson, plate, narrow}) {
    const Case c = make_case(json);
    const glm::ivec2 stride = c.plan.lattice.repeats;
    ASSERT_GT(stride.x * stride.y, 1) << json;
    const double period_x = 2 * kPi / c.plan.lattice.frequency.x;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-0.95, 0.95), lambda(360.0, 830.0);
    std::vector<std::pair<double, double>> values;  // (lattice bins, every bin)
    double largest = 0.0;
    for (int q = 0; q < 400; ++q) {
      const glm::dvec2 i(0.6 * unit(rng), 0.6 * unit(rng));
      const double l = lambda(rng);
      // Half the views on the first order at this wavelength (where the values are large), half anywhere.
      const glm::dvec2 r = q % 2 ? glm::dvec2(unit(rng), unit(rng)) : -glm::dvec2(l / period_x, 0.0) - i;
      if (glm::dot(r, r) >= 1.0) continue;
      const DiffractionQuery query{direction(i.x, i.y), direction(r.x, r.y), l};
      values.emplace_back(evaluate_taylor(c.tables, query, stride).brdf, evaluate_taylor(c.tables, query).brdf);
      largest = std::max(largest, values.back().second);
    }
    ASSERT_GT(largest, 0.0);
    for (const auto& [lattice, every] : values) EXPECT_NEAR(lattice, every, 1e-9 * largest) << json;
    for (double a = -0.05; a <= 0.05; a += 1e-4) {  // bins visited per axis: at most 2r / P + 1 of 2r + 1
      const k64::DiffractionWindowBins bins =
          k64::diffraction_window_bins(glm::dvec2(a, 0.0), c.tables.period_nm, c.tables.r, stride);
      EXPECT_LE(bins.count.x, 2 * c.tables.r / stride.x + 1) << json;
      if (stride.x > 1) most_lattice_bins = std::max(most_lattice_bins, bins.count.x);
    }
  }
  EXPECT_EQ(most_lattice_bins, 2);  // the narrow window's lattice sums add several bins
}

// The window's bins with a stride are exactly the multiples of the stride among the bins within r
// of the nearest one (brute force over frequencies, radii and strides, negative bins included).
TEST(Orders, WindowBinsAreTheStridesMultiplesInTheWindow) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> alpha(-0.05, 0.05);
  const double period = 4000.0;
  for (int q = 0; q < 300; ++q) {
    const glm::dvec2 a(alpha(rng), alpha(rng));
    const int r = q % 4;
    const glm::ivec2 stride(1 + q % 5, 1 + (q / 5) % 7);
    const k64::DiffractionWindowBins bins = k64::diffraction_window_bins(a, period, r, stride);
    std::vector<glm::ivec2> got, want;
    for (int b = 0; b < bins.count.x * bins.count.y; ++b) got.push_back(k64::diffraction_window_bin(bins, b));
    const int jx0 = k64::diffraction_nearest_bin(a.x, period), jy0 = k64::diffraction_nearest_bin(a.y, period);
    for (int jy = jy0 - r; jy <= jy0 + r; ++jy)
      for (int jx = jx0 - r; jx <= jx0 + r; ++jx)
        if (jx % stride.x == 0 && jy % stride.y == 0) want.emplace_back(jx, jy);
    EXPECT_EQ(got, want) << q;
  }
}

// Every wavelength at which order j's window weight reaches the tolerance lies in j's interval
// (and j in the span), found by a 0.02 nm scan over 360..830 nm; every node of the interval does.
TEST(Orders, IntervalsHoldEveryReachingWavelength) {
  const Case c = make_case(kCrossedJson);
  const k64::DiffractionOrderLattice& L = c.plan.lattice;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> uv(-1.2, 1.2);
  for (int q = 0; q < 40; ++q) {
    const glm::dvec2 p(uv(rng), uv(rng));
    const k64::DiffractionOrderSpan span = k64::diffraction_order_span(L, p, glm::dvec2(0.0));
    for (int jy = span.lo.y - 2; jy <= span.hi.y + 2; ++jy)
      for (int jx = span.lo.x - 2; jx <= span.hi.x + 2; ++jx) {
        const glm::ivec2 j(jx, jy);
        const bool in_span = jx >= span.lo.x && jx <= span.hi.x && jy >= span.lo.y && jy <= span.hi.y;
        const k64::DiffractionOrderInterval I = k64::diffraction_order_interval(L, p, j, 0.0);
        const double hi = I.lambda_lo + I.nodes * I.step;
        auto reaches = [&](double l) { return glm::length(2 * kPi / l * p - glm::dvec2(j) * L.frequency) <= L.reach; };
        for (double l = kCieLambdaMinNm; l <= kCieLambdaMaxNm; l += 0.02)
          if (reaches(l)) {
            EXPECT_TRUE(in_span) << q << " j " << jx << "," << jy;
            EXPECT_TRUE(I.nodes > 0 && l >= I.lambda_lo - 1e-9 && l <= hi + 1e-9)
                << q << " j " << jx << "," << jy << " " << l;
          }
        for (int i = 0; i < I.nodes; ++i) EXPECT_TRUE(reaches(k64::diffraction_order_lambda(I, i))) << q;
      }
  }
}

// Directions that put (u, v) on order m of the x period (period_x) at a random wavelength, slightly
// off it in v, or anywhere: the colours the orders path gives and `reference` agree within the
// tolerance's budget (window truncation + midpoint rule, 2 tol of the largest channel) plus the
// observer table's linear interpolation (1e-4 of the query's largest channel), plus the tails beyond
// the intervals (tol^2 of the brightest query). Returns the worst error over the query's brightest
// channel (queries above 1e-3 of the peak).
template <class Reference>
double worst_against(const Case& c, double period_x, int queries, const std::string& label,
                     const Reference& reference) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, peak = 0.0;
  std::vector<std::pair<glm::dvec3, glm::dvec3>> results;  // (orders, reference)
  for (int q = 0; q < queries; ++q) {
    const glm::dvec3 wi = direction(0.6 * unit(rng) - 0.3, 0.2 * unit(rng) - 0.1);
    glm::dvec2 uv(2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0);
    if (q % 3 != 2)
      uv = glm::dvec2((q % 2 ? 1 : -1) * (400.0 + 300.0 * unit(rng)) / period_x, 0.002 * (unit(rng) - 0.5));
    const glm::dvec2 r = -uv - glm::dvec2(wi);
    if (glm::dot(r, r) >= 1.0) continue;
    const glm::dvec3 wr = direction(r.x, r.y);
    results.emplace_back(evaluate_orders(c.tables, c.plan, wi, wr), reference(wi, wr));
    peak = std::max(peak, glm::length(results.back().second));
  }
  // Outside every interval the windows are below tol, so the BRDF is below tol^2 of a peak.
  for (const auto& [got, want] : results) {
    const double scale = std::max({std::abs(want.x), std::abs(want.y), std::abs(want.z)});
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_LE(std::abs(got[ch] - want[ch]), (2 * kTolerance + 1e-4) * scale + kTolerance * kTolerance * peak)
          << label;
      if (scale > 1e-3 * peak) worst = std::max(worst, std::abs(got[ch] - want[ch]) / scale);
    }
  }
  return worst;
}

TEST(Orders, ColoursMatchTheSpectralPath) {
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson}) {
    const Case c = make_case(json);
    ASSERT_TRUE(c.plan.restricted) << json;
    const WavelengthSamples dense = wavelength_samples(0.25);
    const double worst =
        worst_against(c, 2 * kPi / c.plan.lattice.frequency.x, 60, json,
                      [&](const glm::dvec3& wi, const glm::dvec3& wr) { return spectral(c, dense, wi, wr); });
    std::printf("%s: worst |orders - spectral| / brightest channel (queries above 1e-3 of the peak) = %.3g\n", json,
                worst);
  }
}

// Scanning the view across the first order (u from 0.3 to 0.8 in steps of 1e-3 at v = 0): the
// brightest Y of each channel's peak is found at the same step by both paths.
TEST(Orders, PeaksSitWhereTheSpectralPathPutsThem) {
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson}) {
    const Case c = make_case(json);
    const glm::dvec3 wi = direction(0.0, 0.0);
    int argmax_orders = -1, argmax_spectral = -1;
    double max_orders = -1.0, max_spectral = -1.0;
    for (int i = 0; i <= 500; ++i) {
      const glm::dvec3 wr = direction(-(0.3 + 1e-3 * i), 0.0);
      const double a = evaluate_orders(c.tables, c.plan, wi, wr).g, b = spectral(c, c.plan.fallback, wi, wr).g;
      if (a > max_orders) max_orders = a, argmax_orders = i;
      if (b > max_spectral) max_spectral = b, argmax_spectral = i;
    }
    EXPECT_EQ(argmax_orders, argmax_spectral) << json;
    EXPECT_NEAR(max_orders, max_spectral, 3 * kTolerance * max_spectral) << json;
  }
}

// BRDF evaluations per pixel (nodes of all intervals) averaged over the upper hemisphere of views
// under a light at 30 degrees. Deterministic (no timing).
double nodes_per_pixel(const Case& c) {
  const glm::dvec3 wi = direction(0.5, 0.0);
  double nodes = 0.0;
  int pixels = 0;
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j) {
      const glm::dvec2 r(i / 21.0, j / 21.0);
      if (glm::dot(r, r) >= 1.0) continue;
      const glm::dvec2 uv = -r - glm::dvec2(wi);
      const k64::DiffractionOrderSpan span = k64::diffraction_order_span(c.plan.lattice, uv, glm::dvec2(0.0));
      for (int jy = span.lo.y; jy <= span.hi.y; ++jy)
        for (int jx = span.lo.x; jx <= span.hi.x; ++jx)
          nodes += k64::diffraction_order_interval(c.plan.lattice, uv, glm::ivec2(jx, jy), 0.0).nodes;
      ++pixels;
    }
  return nodes / pixels;
}

// The work the restriction saves: nodes_per_pixel against the spectral path's wavelength count at
// the same tolerance.
TEST(Orders, EvaluatesFarFewerWavelengthsThanTheSpectralPath) {
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson}) {
    const Case c = make_case(json);
    const double per_pixel = nodes_per_pixel(c), spectral_count = static_cast<double>(c.plan.fallback.lambda_nm.size());
    std::printf("%s: %.1f evaluations per pixel against %.0f wavelengths\n", json, per_pixel, spectral_count);
    EXPECT_LT(per_pixel * 3.0, spectral_count) << json;
  }
}

// scenes/diffraction_crossed_rotated.json's grating (1200 x 2000 nm over 12 um, 96 samples asked).
// Sampled at 96 (9.6 samples per x period) the patch repeats only gcd(96, 10) = 2 times along x: a
// lattice 5x denser than the grating's, with more candidate orders per pixel than F.10 allows, so
// `orders` was the spectral path. The parser raises the count to 120 (12 and 20 samples per period):
// the walk is the grating's own (10, 6) lattice, agrees with the spectral path at 0.25 nm within
// ColoursMatchTheSpectralPath's bound and with the exact transform (Chebyshev-interpolated, error
// < 1e-12), and walks far fewer nodes. A lattice denser than the grating's is still right where the
// window resolves it: a sinusoid of 4 periods on 62 samples (15.5 per period, 2 repeats) agrees too.
TEST(Orders, CrossedRotatedGratingWalksItsOwnLattice) {
  const Case whole = make_case(
      R"({"type":"crossed","period_nm":[1200,2000],"amplitude_nm":100,"size_um":12,"samples":96,"coherence_um":6})");
  Grating sampled = whole.grating;
  sampled.samples = 96;
  sampled.sample_nm = 125.0;
  sampled.height_nm = crossed_heights({96, 125.0}, 1200.0, 2000.0, 100.0);
  const Case aliased = make_case(sampled);
  EXPECT_EQ(whole.grating.samples, 120);
  EXPECT_EQ(whole.plan.lattice.repeats, glm::ivec2(10, 6));
  EXPECT_EQ(aliased.plan.lattice.repeats, glm::ivec2(2, 6));
  EXPECT_GT(aliased.plan.worst_orders, kMaxOrdersPerPixel);
  EXPECT_FALSE(aliased.plan.restricted);
  ASSERT_TRUE(whole.plan.restricted);
  const WavelengthSamples dense = wavelength_samples(0.25);
  const double worst = worst_against(whole, 1200.0, 60, "120 samples", [&](const glm::dvec3& wi, const glm::dvec3& wr) {
    return spectral(whole, dense, wi, wr);
  });
  const ChebyshevTransform exact(whole.grating, whole.tables);
  const double worst_exact = worst_against(whole, 1200.0, 60, "exact", [&](const glm::dvec3& wi, const glm::dvec3& wr) {
    return integrate_linear_srgb(dense, [&](double l) { return exact.evaluate({wi, wr, l}).brdf; });
  });
  const double whole_nodes = nodes_per_pixel(whole), aliased_nodes = nodes_per_pixel(aliased);
  const double spectral_count = static_cast<double>(whole.plan.fallback.lambda_nm.size());
  std::printf(
      "120 samples: worst |orders - spectral| / brightest channel = %.3g, |orders - exact| %.3g; evaluations "
      "per pixel: %.1f (120 samples), %.1f (96, F.11 expects %.0f), against %.0f wavelengths\n",
      worst, worst_exact, whole_nodes, aliased_nodes, aliased.plan.expected_nodes, spectral_count);
  EXPECT_LT(whole_nodes * 3.0, aliased_nodes);
  EXPECT_LT(whole_nodes * 3.0, spectral_count);

  Grating sinusoid = test::grating(kSinusoidJson);
  sinusoid.samples = 62;
  sinusoid.sample_nm = 4000.0 / 62;
  sinusoid.height_nm = sinusoid_heights({62, sinusoid.sample_nm}, 1000.0, 60.0);
  const Case denser = make_case(sinusoid);
  EXPECT_EQ(denser.plan.lattice.repeats, glm::ivec2(2, 62));
  ASSERT_TRUE(denser.plan.restricted);
  const double worst_denser =
      worst_against(denser, 1000.0, 60, "62 samples",
                    [&](const glm::dvec3& wi, const glm::dvec3& wr) { return spectral(denser, dense, wi, wr); });
  std::printf("sinusoid on 62 samples (2 repeats): worst |orders - spectral| / brightest channel = %.3g\n",
              worst_denser);
}

// F.13 against brute force: the nodes of every candidate's interval, summed per view, never exceed
// plan.most_nodes, over views of the whole hemisphere and near the specular direction (where the
// low orders' intervals are the longest), for lattices with separated and with overlapping orders.
TEST(Orders, NodesPerPixelStayWithinTheirBound) {
  const char* plate =
      R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":100,"size_um":8,"samples":80,"coherence_um":3.2})";
  const char* fingers = R"({"type":"fingers","period_nm":750,"amplitude_nm":80,"size_um":3,"samples":48,)"
                        R"("finger_length_nm":1500,"coherence_um":0.75})";
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson, plate, fingers}) {
    const Case c = make_case(json);
    const k64::DiffractionOrderLattice& L = c.plan.lattice;
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double most = 0.0;
    for (int q = 0; q < 4000; ++q) {
      const double scale = q % 2 ? 2.0 : 0.02;  // anywhere, or within 0.02 of specular
      const glm::dvec2 uv(scale * unit(rng), scale * unit(rng));
      const k64::DiffractionOrderSpan span = k64::diffraction_order_span(L, uv, glm::dvec2(0.0));
      double nodes = 0.0;
      for (int i = 0; i < k64::diffraction_order_candidates(span); ++i)
        nodes += k64::diffraction_order_interval(L, uv, k64::diffraction_order_candidate(span, i), 0.0).nodes;
      EXPECT_LE(nodes, c.plan.most_nodes) << json << " " << uv.x << "," << uv.y;
      most = std::max(most, nodes);
    }
    std::printf("%s: most nodes per view %.0f, bound %.0f\n", json, most, c.plan.most_nodes);
  }
}

// A random height field has no period inside its patch: the plan says so and evaluate_orders is
// exactly the spectral path on the fallback samples.
TEST(Orders, RandomHeightFieldFallsBackToSpectral) {
  Grating g = test::grating(kSinusoidJson);
  std::mt19937 rng(9);
  std::normal_distribution<double> height(0.0, 30.0);
  for (double& h : g.height_nm) h = height(rng);
  TableRange range;
  range.lambda_min_nm = kCieLambdaMinNm;
  const SpectralTables tables = build_spectral_tables(g, range);
  const OrderWavelengths plan = plan_order_wavelengths(g, tables, kTolerance, Illuminant::D65,
                                                       diffraction_wavelength_samples(tables, kTolerance));
  EXPECT_EQ(patch_repeats(g).x, 1);
  EXPECT_EQ(patch_repeats(g).y, 1);
  EXPECT_FALSE(plan.restricted);
  EXPECT_GT(plan.worst_orders, kMaxOrdersPerPixel);
  const glm::dvec3 wi = direction(0.2, 0.1);
  for (double x : {-0.5, -0.2, 0.1}) {
    const glm::dvec3 wr = direction(x, 0.05);
    const glm::dvec3 want = integrate_linear_srgb(plan.fallback, [&](double l) {
      return evaluate_taylor(tables, {wi, wr, l}).brdf;
    });
    EXPECT_EQ(evaluate_orders(tables, plan, wi, wr), want);
  }
}

// The GPU (float, lavapipe) runs render/diffraction_orders.glsl: on views across the orders of
// each grating it agrees with the double twin within 1e-4 of the query's brightest channel (the
// float Taylor BRDF's own error, docs/diffraction.md, plus float node positions) and tol^2 of the
// brightest query.
TEST(Orders, GpuMatchesTheDoubleTwin) {
  auto context = test::make_validated_context();
  for (const char* json : {kSinusoidJson, kCrossedJson}) {
    const Case c = make_case(json);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
    const glm::dvec3 wi = direction(0.2, 0.05);
    while (pairs.size() < 256) {
      const glm::dvec2 uv((400.0 + 300.0 * unit(rng)) / 1000.0, 0.002 * (unit(rng) - 0.5));
      const glm::dvec2 r = -uv - glm::dvec2(wi);
      if (glm::dot(r, r) < 1.0) pairs.emplace_back(wi, direction(r.x, r.y));
    }
    const test::ProbeRun run = test::run_orders_probe(*context, c.tables, c.plan, pairs);
    std::vector<glm::dvec3> want;
    double peak = 0.0, worst = 0.0;
    for (const auto& [a, b] : pairs) {
      want.push_back(evaluate_orders(c.tables, c.plan, a, b));
      peak = std::max(peak, glm::length(want.back()));
    }
    for (size_t q = 0; q < pairs.size(); ++q) {
      const double scale = std::max({std::abs(want[q].x), std::abs(want[q].y), std::abs(want[q].z)});
      for (int ch = 0; ch < 3; ++ch) {
        const double error = std::abs(run.rgb[q][ch] - want[q][ch]);
        EXPECT_LE(error, 1e-4 * scale + kTolerance * kTolerance * peak) << json << " " << q;
        if (scale > 1e-3 * peak) worst = std::max(worst, error / scale);
      }
    }
    std::printf("GPU vs double twin, %s: worst |error| / brightest channel = %.3g\n", json, worst);
  }
}

// The flat walk of render/diffraction_orders.glsl (one loop over a pixel's nodes, advancing through
// its candidates) on views all over the hemisphere of the crossed grating, where neighbouring
// queries have different spans, empty candidates and several orders: same bound as above.
TEST(Orders, GpuMatchesTheDoubleTwinOverTheHemisphere) {
  auto context = test::make_validated_context();
  const Case c = make_case(kCrossedJson);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  while (pairs.size() < 512) {
    const glm::dvec2 i(0.7 * unit(rng), 0.7 * unit(rng)), r(unit(rng), unit(rng));
    if (glm::dot(i, i) < 1.0 && glm::dot(r, r) < 1.0) pairs.emplace_back(direction(i.x, i.y), direction(r.x, r.y));
  }
  const test::ProbeRun run = test::run_orders_probe(*context, c.tables, c.plan, pairs);
  std::vector<glm::dvec3> want;
  double peak = 0.0, worst = 0.0;
  int lit = 0;
  for (const auto& [a, b] : pairs) {
    want.push_back(evaluate_orders(c.tables, c.plan, a, b));
    peak = std::max(peak, glm::length(want.back()));
  }
  for (size_t q = 0; q < pairs.size(); ++q) {
    const double scale = std::max({std::abs(want[q].x), std::abs(want[q].y), std::abs(want[q].z)});
    lit += scale > 1e-3 * peak;
    for (int ch = 0; ch < 3; ++ch) {
      const double error = std::abs(run.rgb[q][ch] - want[q][ch]);
      EXPECT_LE(error, 1e-4 * scale + kTolerance * kTolerance * peak) << q;
      if (scale > 1e-3 * peak) worst = std::max(worst, error / scale);
    }
  }
  EXPECT_GT(lit, 10);  // the views do meet orders
  std::printf("GPU vs double twin over the hemisphere: %d lit views, worst |error| / brightest channel = %.3g\n", lit,
              worst);
}

// F.11 against brute force. The mean number of orders within the reach of a random point of the
// (u, v) k plane is pi rho^2 / (f_x f_y) (counted over 20000 points, within 5 %), and the nodes a
// pixel costs (every candidate's interval, counted like EvaluatesFarFewer...) average at least
// expected_nodes over views of the hemisphere. The snake's fingers (scenes/snake_fingers.json:
// window 750 nm, lattice 750 x 3000 nm) overlap ~4 orders everywhere: restricting would cost ~9x
// the spectral wavelengths, so the plan falls back; the sinusoid's well separated orders do not.
TEST(Orders, WindowsTooWideForTheLatticeFallBackToSpectral) {
  const Case snake = make_case(R"({"type":"fingers","period_nm":750,"amplitude_nm":80,"size_um":3,"samples":48,)"
                               R"("finger_length_nm":1500,"coherence_um":0.75})");
  const k64::DiffractionOrderLattice& L = snake.plan.lattice;
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double within = 0.0;
  const int points = 20000;
  for (int q = 0; q < points; ++q) {
    const glm::dvec2 p = glm::dvec2(unit(rng), unit(rng)) * L.frequency;  // one lattice cell suffices
    for (int jy = -5; jy <= 5; ++jy)
      for (int jx = -5; jx <= 5; ++jx) within += glm::length(p - glm::dvec2(jx, jy) * L.frequency) <= L.reach;
  }
  const double overlap = kPi * L.reach * L.reach / (L.frequency.x * L.frequency.y);
  EXPECT_NEAR(within / points, overlap, 0.05 * overlap);
  EXPECT_NEAR(snake.plan.expected_nodes, overlap * (kCieLambdaMaxNm - kCieLambdaMinNm) / L.max_step, 1e-9);
  double nodes = 0.0;
  int pixels = 0;
  for (int q = 0; q < 2000; ++q) {
    const glm::dvec2 i(2 * unit(rng) - 1, 2 * unit(rng) - 1), r(2 * unit(rng) - 1, 2 * unit(rng) - 1);
    if (glm::dot(i, i) >= 1.0 || glm::dot(r, r) >= 1.0) continue;
    const glm::dvec2 uv = -(i + r);
    const k64::DiffractionOrderSpan span = k64::diffraction_order_span(L, uv, glm::dvec2(0.0));
    for (int c = 0; c < k64::diffraction_order_candidates(span); ++c)
      nodes += k64::diffraction_order_interval(L, uv, k64::diffraction_order_candidate(span, c), 0.0).nodes;
    ++pixels;
  }
  const double spectral_count = static_cast<double>(snake.plan.fallback.lambda_nm.size());
  std::printf("snake fingers: overlap %.2f, %.0f nodes per pixel measured, %.0f expected, %.0f wavelengths\n", overlap,
              nodes / pixels, snake.plan.expected_nodes, spectral_count);
  EXPECT_GE(nodes / pixels, snake.plan.expected_nodes);
  EXPECT_GT(snake.plan.expected_nodes, spectral_count);
  EXPECT_FALSE(snake.plan.restricted);
  const glm::dvec3 wi = direction(0.2, 0.3), wr = direction(-0.5, 0.1);
  EXPECT_EQ(evaluate_orders(snake.tables, snake.plan, wi, wr), spectral(snake, snake.plan.fallback, wi, wr));
  const Case sinusoid = make_case(kSinusoidJson);
  EXPECT_TRUE(sinusoid.plan.restricted);
  EXPECT_LT(sinusoid.plan.expected_nodes, 1.0);
}

// Grazing and extreme directions give finite colours.
TEST(Orders, FiniteOnTheWholeDomain) {
  const Case c = make_case(kCrossedJson);
  for (double ix : {-1.0, 0.0, 0.7})
    for (double rx : {-1.0, -0.3, 0.0, 1.0})
      for (double ry : {-1.0, 0.0, 1e-12}) {
        const glm::dvec3 wr = glm::normalize(glm::dvec3(rx, ry, std::sqrt(std::max(0.0, 1 - rx * rx - ry * ry))));
        const glm::dvec3 rgb = evaluate_orders(c.tables, c.plan, direction(ix, 0.0), wr);
        for (int ch = 0; ch < 3; ++ch) EXPECT_TRUE(std::isfinite(rgb[ch])) << ix << " " << rx << " " << ry;
      }
}

}  // namespace orders_test
}  // namespace facet
