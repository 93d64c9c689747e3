// The orders over a pixel (docs/diffraction_fast_paths.md, "Orders over the pixel", eqs. O1-O3): a pixel
// whose (u, v) sweeps a parallelogram gets the mean of the orders' colours over it. Checked against the
// colour at a point (zero steps), against midpoint quadrature of point colours over the parallelogram, the
// widened intervals against a scan of every wavelength some of the pixel reaches, the node budget, extreme
// pixels, and the GPU against the double twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "order_cases.hpp"
#include "orders_probe.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace orders_over_pixel_test {

using namespace diffraction;
using namespace order_cases;
using test::direction;
using test::kPi;
namespace k64 = kernels::f64;

// The light's direction and the view whose (u, v) = -(wi + wr)_xy is uv.
const glm::dvec3 kLight = direction(0.25, 0.05);

glm::dvec3 view_at(const glm::dvec2& uv) {
  const glm::dvec2 r = -uv - glm::dvec2(kLight);
  return direction(r.x, r.y);
}

double brightest(const glm::dvec3& c) { return std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}); }

// The window's width in (u, v) at 550 nm, 1 / (k sigma): the scale of an order's peak.
double window_width(const Case& c) { return 550.0 / (2.0 * kPi * c.plan.lattice.sigma_nm); }

// (u, v) on order (m, 0) at wavelength lambda, shifted by `offset` window widths.
glm::dvec2 on_order(const Case& c, int m, double lambda_nm, const glm::dvec2& offset) {
  const double f = c.plan.lattice.frequency.x;
  return glm::dvec2(m * f * lambda_nm / (2.0 * kPi), 0.0) + offset * window_width(c);
}

// Midpoint quadrature over the pixel uv + a step_x + b step_y, a, b in [-1/2, 1/2], of the point colour.
glm::dvec3 pixel_quadrature(const Case& c, const glm::dvec2& uv, const glm::dvec4& steps, int n) {
  glm::dvec3 sum(0.0);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double s = (a + 0.5) / n - 0.5, t = (b + 0.5) / n - 0.5;
      const glm::dvec2 p = uv + s * glm::dvec2(steps.x, steps.y) + t * glm::dvec2(steps.z, steps.w);
      sum += evaluate_orders(c.tables, c.plan, kLight, view_at(p));
    }
  return sum / double(n * n);
}

// O2 at a point: with zero steps each order's own bin weighed by its window is the window sum weighed by
// the orders' shares (F.8), up to the window sum's cross terms between orders, which for these gratings
// (orders sigma f = 50 window radii apart) are below exp(-sigma^2 f^2 / 4), i.e. 0 in double.
TEST(OrdersOverPixel, APointPixelIsTheColourAtItsCentre) {
  for (const char* json : {kSinusoidJson, kRectangularJson, kCrossedJson}) {
    const Case c = make_case(json);
    double worst = 0.0;
    for (int m = -2; m <= 2; ++m)
      for (double lambda : {420.0, 510.0, 640.0})
        for (double off : {0.0, 0.7, 2.0}) {
          const glm::dvec2 uv = on_order(c, m, lambda, glm::dvec2(off, 0.3 * off));
          const glm::dvec3 point = evaluate_orders(c.tables, c.plan, kLight, view_at(uv));
          const glm::dvec3 mean = evaluate_orders(c.tables, c.plan, kLight, view_at(uv), glm::dvec4(0.0));
          const double scale = std::max(brightest(point), 1e-12);
          worst = std::max(worst, brightest(mean - point) / scale);
          EXPECT_LE(brightest(mean - point), 1e-9 * scale) << json << " m " << m << " lambda " << lambda;
        }
    std::printf("%s: a point pixel's worst |mean - point| / brightest channel = %.3g\n", json, worst);
  }
}

// O2 over pixels from a fifth of a window to 8 windows wide, square, rotated and sheared, with the peak at
// the centre, off centre and near a corner: against 48 x 48 midpoint samples of the point colour (a sample
// spacing of at most a sixth of a window, which the midpoint rule integrates to ~1e-9). What O2 leaves out:
// the BRDF's smooth factors (|T_j|^2, the cosines, Schlick) are taken at the centre, a first-order change
// of 2 % per window-width of (u, v) at most here, and a sheared pixel's mean of the window is
// normal_density_over_parallelogram's (4.3e-3 of the peak, docs/microsurface_filtering.md, P2).
TEST(OrdersOverPixel, MeanOverThePixelIsTheMeanOfItsPoints) {
  struct Shape {
    glm::dvec2 x, y;  // steps in window widths
  };
  const Shape shapes[] = {{{0.2, 0.0}, {0.0, 0.2}},  {{1.0, 0.0}, {0.0, 1.0}},  {{3.0, 0.0}, {0.0, 0.5}},
                          {{2.0, 2.0}, {-1.0, 1.0}}, {{8.0, 1.0}, {-0.5, 4.0}}, {{2.0, 0.0}, {1.5, 1.0}}};
  const glm::dvec2 offsets[] = {{0.0, 0.0}, {0.4, -0.3}, {1.5, 0.9}, {-3.0, 2.0}};
  for (const char* json : {kSinusoidJson, kCrossedJson}) {
    const Case c = make_case(json);
    const double w = window_width(c);
    double worst = 0.0, peak = 0.0;
    for (const Shape& shape : shapes)
      for (const glm::dvec2& offset : offsets) {
        const glm::dvec2 uv = on_order(c, 1, 530.0, offset);
        const glm::dvec4 steps(shape.x * w, shape.y * w);
        const glm::dvec3 want = pixel_quadrature(c, uv, steps, 48);
        const glm::dvec3 got = evaluate_orders(c.tables, c.plan, kLight, view_at(uv), steps);
        peak = std::max(peak, brightest(want));
        const double error = brightest(got - want);
        worst = std::max(worst, error / std::max(brightest(want), 1e-300));
        EXPECT_LE(error, 0.03 * brightest(want) + 1e-3 * peak)
            << json << " steps " << steps.x << "," << steps.y << "," << steps.z << "," << steps.w << " offset "
            << offset.x << "," << offset.y;
      }
    std::printf("%s: worst |pixel mean - quadrature| / brightest channel = %.3g\n", json, worst);
  }
}

// The point colours at the pixels' centres miss a peak narrower than a pixel or count it whole; the pixels'
// means keep its integral: over a block of 7 x 7 pixels, each three windows wide, tiling
// the peak at four sub-pixel phases, the sum of the means is the block's quadrature within 1 %.
TEST(OrdersOverPixel, APeakNarrowerThanAPixelKeepsItsIntegralOverABlock) {
  const Case c = make_case(kSinusoidJson);
  const double w = window_width(c);
  const glm::dvec4 steps(3.0 * w, 0.0, 0.0, 3.0 * w);
  for (const glm::dvec2 phase : {glm::dvec2(0.0), glm::dvec2(0.5, 0.0), glm::dvec2(0.25, 0.4), glm::dvec2(0.5, 0.5)}) {
    glm::dvec3 means(0.0), centres(0.0), block(0.0);
    for (int y = -3; y <= 3; ++y)
      for (int x = -3; x <= 3; ++x) {
        const glm::dvec2 uv = on_order(c, 1, 530.0, 3.0 * (glm::dvec2(x, y) + phase));
        means += evaluate_orders(c.tables, c.plan, kLight, view_at(uv), steps);
        centres += evaluate_orders(c.tables, c.plan, kLight, view_at(uv));
        block += pixel_quadrature(c, uv, steps, 24);
      }
    EXPECT_LE(brightest(means - block), 0.01 * brightest(block)) << phase.x << "," << phase.y;
    std::printf("phase (%.2f, %.2f): block %.4g, pixel means %.4g, centres %.4g (green)\n", phase.x, phase.y, block.y,
                means.y, centres.y);
  }
}

// O1: every wavelength at which some of the pixel's (u, v) (a 9 x 9 grid over it) comes within the reach of
// order j lies in j's widened interval, and j in the widened span; pixels up to the reach's cap, some holding
// (u, v) = 0.
TEST(OrdersOverPixel, IntervalsHoldEveryWavelengthThePixelReaches) {
  const Case c = make_case(kCrossedJson);
  const k64::DiffractionOrderLattice& L = c.plan.lattice;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double cap = L.pixel_reach / L.k_max;
  for (int q = 0; q < 30; ++q) {
    const glm::dvec2 uv =
        q < 5 ? glm::dvec2(0.3 * cap * unit(rng), 0.3 * cap * unit(rng)) : glm::dvec2(1.1 * unit(rng), 1.1 * unit(rng));
    const glm::dvec4 steps =
        k64::diffraction_pixel_steps(L, glm::dvec4(unit(rng), unit(rng), unit(rng), unit(rng)) * (2.0 * cap));
    const glm::dvec2 half_extent = k64::diffraction_pixel_half_extent(steps);
    const k64::DiffractionOrderSpan span = k64::diffraction_order_span(L, uv, half_extent);
    for (int jy = span.lo.y - 1; jy <= span.hi.y + 1; ++jy)
      for (int jx = span.lo.x - 1; jx <= span.hi.x + 1; ++jx) {
        const glm::ivec2 j(jx, jy);
        const bool in_span = jx >= span.lo.x && jx <= span.hi.x && jy >= span.lo.y && jy <= span.hi.y;
        const k64::DiffractionOrderInterval I = k64::diffraction_order_interval(L, uv, j, glm::length(half_extent));
        const double hi = I.lambda_lo + I.nodes * I.step;
        for (double l = kCieLambdaMinNm; l <= kCieLambdaMaxNm; l += 0.25) {
          bool reaches = false;
          for (int b = 0; b < 9 && !reaches; ++b)
            for (int a = 0; a < 9 && !reaches; ++a) {
              const glm::dvec2 p =
                  uv + (a / 8.0 - 0.5) * glm::dvec2(steps.x, steps.y) + (b / 8.0 - 0.5) * glm::dvec2(steps.z, steps.w);
              reaches = glm::length(2 * kPi / l * p - glm::dvec2(j) * L.frequency) <= L.reach;
            }
          if (!reaches) continue;
          EXPECT_TRUE(in_span) << q << " j " << jx << "," << jy;
          EXPECT_TRUE(I.nodes > 0 && l >= I.lambda_lo - 1e-9 && l <= hi + 1e-9)
              << q << " j " << jx << "," << jy << " " << l;
        }
      }
  }
}

// O3: a pixel whose orders want more nodes than the budget gets each order's cut alike: the walk's total
// stays within budget + orders, every order keeps at least one node, and the colour stays near the full one
// (a coarser midpoint rule over the same intervals).
TEST(OrdersOverPixel, TheNodeBudgetCutsEveryOrderAlike) {
  Case c = make_case(kCrossedJson);
  const double w = window_width(c);
  const glm::dvec2 uv = on_order(c, 1, 530.0, glm::dvec2(0.0));
  const glm::dvec4 steps(12.0 * w, 0.0, 0.0, 12.0 * w);
  const glm::dvec3 full = evaluate_orders(c.tables, c.plan, kLight, view_at(uv), steps);
  k64::DiffractionOrderLattice& L = c.plan.lattice;
  const k64::DiffractionOrderSpan span =
      k64::diffraction_order_span(L, uv, k64::diffraction_pixel_half_extent(k64::diffraction_pixel_steps(L, steps)));
  const double r = glm::length(k64::diffraction_pixel_half_extent(k64::diffraction_pixel_steps(L, steps)));
  int wanted = 0, orders = 0;
  for (int i = 0; i < k64::diffraction_order_candidates(span); ++i) {
    const int n = k64::diffraction_order_interval(L, uv, k64::diffraction_order_candidate(span, i), r).nodes;
    wanted += n;
    orders += n > 0;
  }
  ASSERT_GT(wanted, 64);
  L.pixel_budget = wanted / 4;
  int total = 0;
  for (int i = 0; i < k64::diffraction_order_candidates(span); ++i) {
    const k64::DiffractionOrderInterval I =
        k64::diffraction_order_interval(L, uv, k64::diffraction_order_candidate(span, i), r);
    const k64::DiffractionOrderInterval cut = k64::diffraction_order_interval_within(I, wanted, L.pixel_budget);
    EXPECT_EQ(cut.nodes > 0, I.nodes > 0);
    if (I.nodes > 0) {
      EXPECT_NEAR(cut.lambda_lo + cut.nodes * cut.step, I.lambda_lo + I.nodes * I.step, 1e-9);
    }
    total += cut.nodes;
  }
  EXPECT_LE(total, L.pixel_budget + orders);
  const glm::dvec3 cut = evaluate_orders(c.tables, c.plan, kLight, view_at(uv), steps);
  EXPECT_LE(brightest(cut - full), 0.05 * brightest(full));
  std::printf("%d nodes wanted, %d within a budget of %d: colour moves by %.3g of its brightest channel\n", wanted,
              total, L.pixel_budget, brightest(cut - full) / brightest(full));
}

// O2 drops the cross terms between orders, up to exp(-sigma^2 f^2 / 4) of the peak: a grating whose window
// (coherence 0.8 um) is too wide against its period (1 um) for that to stay within the tolerance
// (sigma f = 5.0 < 2 sqrt(ln 1000) = 5.3) keeps each pixel's orders at its centre, the coherent window sum.
TEST(OrdersOverPixel, OrdersTooCloseForTheModelStayAtTheCentre) {
  const Case c = make_case(
      R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":60,"size_um":2,"samples":32,"coherence_um":0.8})");
  ASSERT_TRUE(c.plan.restricted);
  EXPECT_EQ(c.plan.lattice.pixel_reach, 0.0);
  EXPECT_GT(make_case(kSinusoidJson).plan.lattice.pixel_reach, 0.0);
  for (double u : {0.1, 0.45, 0.6, 1.1}) {
    const glm::dvec3 wr = view_at(glm::dvec2(u, 0.01));
    EXPECT_EQ(evaluate_orders(c.tables, c.plan, kLight, wr, glm::dvec4(0.02, 0.0, 0.0, 0.02)),
              evaluate_orders(c.tables, c.plan, kLight, wr))
        << u;
  }
}

// Pixels at the extremes: zero, tiny and huge steps (a silhouette's: capped), (u, v) at 0 with a pixel around
// it, grazing views: finite colours.
TEST(OrdersOverPixel, ExtremePixelsStayFinite) {
  const Case c = make_case(kCrossedJson);
  const glm::dvec4 step_cases[] = {glm::dvec4(0.0), glm::dvec4(1e-12, 0.0, 0.0, 1e-12), glm::dvec4(1e3, 2e3, -3e3, 1e3),
                                   glm::dvec4(0.5, 0.0, 0.5, 0.0), glm::dvec4(0.01, 0.0, 0.0, 0.01)};
  const glm::dvec3 views[] = {view_at(glm::dvec2(0.0)), direction(0.999, 0.0), direction(-0.7, 0.7),
                              direction(0.0, -0.9999)};
  for (const glm::dvec4& steps : step_cases)
    for (const glm::dvec3& wr : views) {
      const glm::dvec3 rgb = evaluate_orders(c.tables, c.plan, kLight, wr, steps);
      for (int ch = 0; ch < 3; ++ch) EXPECT_TRUE(std::isfinite(rgb[ch])) << steps.x << " " << wr.x;
    }
}

// The GPU (float, lavapipe) runs the same walk over the pixel: within the bound of Orders.GpuMatchesTheDoubleTwin
// (1e-4 of the query's brightest channel plus tol^2 of the brightest query) on views across the orders, for
// pixels of several shapes.
TEST(OrdersOverPixel, GpuMatchesTheDoubleTwin) {
  auto context = test::make_validated_context();
  for (const char* json : {kSinusoidJson, kCrossedJson}) {
    const Case c = make_case(json);
    const double w = window_width(c);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
    while (pairs.size() < 128) {
      const glm::dvec2 uv((400.0 + 300.0 * unit(rng)) / 1000.0, 0.02 * (unit(rng) - 0.5));
      const glm::dvec2 r = -uv - glm::dvec2(kLight);
      if (glm::dot(r, r) < 1.0) pairs.emplace_back(kLight, direction(r.x, r.y));
    }
    double worst = 0.0;
    for (const glm::dvec4 steps :
         {glm::dvec4(0.5 * w, 0.0, 0.0, 0.5 * w), glm::dvec4(4.0 * w, 1.0 * w, -2.0 * w, 3.0 * w)}) {
      const test::ProbeRun run = test::run_orders_probe(*context, c.tables, c.plan, pairs, steps);
      std::vector<glm::dvec3> want;
      double peak = 0.0;
      for (const auto& [a, b] : pairs) {
        want.push_back(evaluate_orders(c.tables, c.plan, a, b, steps));
        peak = std::max(peak, brightest(want.back()));
      }
      ASSERT_GT(peak, 0.0);
      for (size_t q = 0; q < pairs.size(); ++q) {
        const double scale = brightest(want[q]);
        for (int ch = 0; ch < 3; ++ch) {
          const double error = std::abs(run.rgb[q][ch] - want[q][ch]);
          EXPECT_LE(error, 1e-4 * scale + kTolerance * kTolerance * peak) << json << " " << q;
          if (scale > 1e-3 * peak) worst = std::max(worst, error / scale);
        }
      }
    }
    std::printf("GPU vs double twin over the pixel, %s: worst |error| / brightest channel = %.3g\n", json, worst);
  }
}

}  // namespace orders_over_pixel_test
}  // namespace facet
