// Pre-integrated diffraction tables (docs/diffraction_fast_paths.md) against the per-wavelength
// path with the same wavelength samples and Taylor terms (equal at the nodes up to storage
// rounding, within the interpolation bound F.6 between them), against the exact transform, at the
// domain's edges and grazing angles, in float on the CPU and on the GPU, and refused when too large.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "diffraction/cie_tables.hpp"
#include "diffraction/exact_transform.hpp"
#include "diffraction/preintegrated_tables.hpp"
#include "diffraction_cases.hpp"
#include "kernels/shared.hpp"
#include "preintegrated_probe.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace preintegrated_test {

using namespace diffraction;
using test::direction;

// Coherence 2 um: lobes of width 1/(k sigma) ~ 0.02 in (u, v), so the tables stay small.
const char* kSinusoid =
    R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":60,"size_um":4,"samples":64,"coherence_um":2})";
const char* kFingers = R"({"type":"fingers","period_nm":1000,"amplitude_nm":80,"size_um":4,"samples":64,)"
                       R"("finger_length_nm":1000,"coherence_um":2})";
const char* kCrossed =
    R"({"type":"crossed","period_nm":[1000,800],"amplitude_nm":60,"size_um":4,"samples":80,"coherence_um":2})";

// The scene of every test: a distant light and the views of a camera that sees the specular lobe
// ((u, v) = 0), the first order's blue end (u = lambda / 1000 nm <= 0.5) and the dark between.
const glm::dvec3 kLight = direction(0.3, 0.1);
glm::dvec3 view(double s, double t) { return direction(-0.8 + 0.5 * s, -0.2 + 0.2 * t); }  // s, t in [0, 1]

std::vector<std::pair<glm::dvec3, glm::dvec3>> scene_pairs() {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) pairs.emplace_back(kLight, view(i / 20.0, j / 20.0));
  return pairs;
}

struct Case {
  Grating grating;
  PreintegratedDomain domain;
  SpectralTables tables;
  WavelengthSamples samples;
};

Case make_case(const char* json) {
  Case c{test::grating(json), domain_of_directions(scene_pairs()), {}, {}};
  TableRange range;
  range.lambda_min_nm = kCieLambdaMinNm;
  range.lambda_max_nm = kCieLambdaMaxNm;
  range.w_max = -c.domain.w_min;
  c.tables = build_spectral_tables(c.grating, range);
  c.samples = diffraction_wavelength_samples(c.tables, 1e-3);
  return c;
}

glm::dvec3 spectral_srgb(const Case& c, const glm::dvec3& wi, const glm::dvec3& wr) {
  return integrate_linear_srgb(c.samples, [&](double l) { return evaluate_taylor(c.tables, {wi, wr, l}).brdf; });
}

glm::dvec3 to_xyz(glm::dvec3 rgb) {
  glm::dmat3 m;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0.0);
    e[i] = 1.0;
    m[i] = kernels::f64::spectral_xyz_to_linear_srgb(e);
  }
  return glm::inverse(m) * rgb;
}

// E(wi, wr) = factor x sum: the envelope of F.6 in XYZ, computed from the spectral tables alone.
// Every Gaussian component of the tables' polynomial has at most this amplitude sum at (u, v),
// because |d_m| delta^m summed over m is at most sum_n |c_n| |w_min|^n and
// |c_n| <= sum_j e_j (k h_s)^n/n! |H_n(j)|. factor: the lambda-independent part of F.5.
struct Envelope {
  double factor;
  glm::dvec3 sum;
  glm::dvec3 value() const { return factor * sum; }
};

Envelope envelope(const Case& c, const glm::dvec3& wi, const glm::dvec3& wr) {
  using namespace kernels::f64;
  const SpectralTables& t = c.tables;
  const DiffractionGeometry g0 = diffraction_geometry(wi, wr, c.samples.lambda_nm.back(), t.sigma_nm, t.hs_nm);
  const double s = t.sigma_nm * g0.one_plus_cos / g0.w_resolved;
  const double factor = diffraction_schlick_reflectance(g0, t.R0) * s * s / (test::kPi * g0.cos_i * g0.cos_r);
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < c.samples.lambda_nm.size(); ++i) {
    const double k = 2 * test::kPi / c.samples.lambda_nm[i];
    const glm::dvec2 alpha = -k * glm::dvec2(wi.x + wr.x, wi.y + wr.y);
    const int jx0 = diffraction_nearest_bin(alpha.x, t.period_nm), jy0 = diffraction_nearest_bin(alpha.y, t.period_nm);
    double field = 0.0;
    for (int jy = jy0 - t.r; jy <= jy0 + t.r; ++jy)
      for (int jx = jx0 - t.r; jx <= jx0 + t.r; ++jx) {
        if (!diffraction_table_entry(0, jx, jy, t.J, 1).valid) continue;
        const double e = diffraction_window_weight(alpha - diffraction_bin_frequency(jx, jy, t.period_nm), t.sigma_nm);
        double term = 1.0;
        for (int n = 0; n < t.N; ++n) {
          field += e * term * std::abs(t.coefficients[diffraction_table_entry(n, jx, jy, t.J, t.stored_terms).index]);
          term *= k * t.hs_nm * -c.domain.w_min / (n + 1);
        }
      }
    sum += c.samples.xyz_weight[i] * (k * k * field * field);
  }
  return {factor, sum};
}

// Storage rounding: each coefficient to eps of itself (halves 2^-11, floats 2^-24), which the
// envelope bounds after the Horner sum, plus the halves' subnormal step 2^-25 of the largest |T_p|.
glm::dvec3 storage_bound(const Case& c, const PreintegratedTables& pre, const glm::dvec3& wi, const glm::dvec3& wr) {
  const Envelope e = envelope(c, wi, wr);
  const double delta = std::abs(-(wi.z + wr.z) - pre.w_centre);
  double subnormal = 0.0;
  for (int p = 0; p < pre.terms; ++p) subnormal += std::pow(delta, p) * pre.scale[p] * std::ldexp(1.0, -25);
  const double eps = pre.words == 2 ? std::ldexp(1.0, -11) : std::ldexp(1.0, -24);
  return e.value() * eps + glm::dvec3(e.factor * (pre.words == 2 ? subnormal : 0.0));
}

// The direction toward the viewer that puts (u, v) exactly at `uv` under the scene's light.
glm::dvec3 view_at(glm::dvec2 uv) { return direction(-uv.x - kLight.x, -uv.y - kLight.y); }

double max_component(glm::dvec3 v) { return std::max({v.x, v.y, v.z}); }

// At the nodes bilinear interpolation is exact: what remains is the storage rounding (halves:
// 2^-11 of each coefficient times the amplification, plus their subnormal step 2^-25 of the largest
// coefficient) and the double rounding of the Horner sum.
TEST(Preintegrated, EqualsThePerWavelengthPathAtTheNodes) {
  for (const char* json : {kSinusoid, kFingers, kCrossed}) {
    const Case c = make_case(json);
    const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
    ASSERT_EQ(pre.words, 2) << "this scene is meant to store halves";
    std::mt19937 rng(7);
    double worst = 0.0;
    for (int q = 0; q < 60; ++q) {
      const glm::dvec2 uv = pre.origin + glm::dvec2(rng() % pre.nu, rng() % pre.nv) * pre.spacing;
      const glm::dvec3 wr = view_at(uv);
      const glm::dvec3 want = to_xyz(spectral_srgb(c, kLight, wr));
      const glm::dvec3 got = to_xyz(evaluate_preintegrated(pre, kLight, wr));
      const glm::dvec3 bound = storage_bound(c, pre, kLight, wr) + 1e-12 * max_component(glm::abs(want));
      for (int ch = 0; ch < 3; ++ch) {
        EXPECT_LE(std::abs(got[ch] - want[ch]), bound[ch] + 1e-12)
            << json << " node " << uv.x << "," << uv.y << " want " << want[ch] << " got " << got[ch] << " E "
            << envelope(c, kLight, wr).value()[ch];
        if (bound[ch] > 0) worst = std::max(worst, std::abs(got[ch] - want[ch]) / bound[ch]);
      }
    }
    std::printf("nodes, %s: worst |error| / bound = %.3g\n", json, worst);
  }
}

// Between the nodes the error stays within tol x the envelope (F.6, the envelope taken as the
// largest of its values at the query and the cell's corners, doubled for the Gaussians' shoulders,
// where |g''| / g reaches (2 b x^2 - 1) b > 2 b), plus the storage rounding above.
TEST(Preintegrated, InterpolationErrorWithinTheDerivedBound) {
  const PreintegrationSettings settings;  // tol 1e-2
  for (const char* json : {kSinusoid, kFingers, kCrossed}) {
    const Case c = make_case(json);
    const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain, settings);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0, peak = 0.0, largest_error = 0.0;
    for (int q = 0; q < 150; ++q) {
      const glm::dvec3 wr = view(unit(rng), unit(rng));
      const glm::dvec2 uv = -glm::dvec2(kLight.x + wr.x, kLight.y + wr.y);
      const glm::dvec2 cell = glm::floor((uv - pre.origin) / pre.spacing);
      glm::dvec3 env = envelope(c, kLight, wr).value();
      for (int corner = 0; corner < 4; ++corner) {
        const glm::dvec2 node = pre.origin + (cell + glm::dvec2(corner % 2, corner / 2)) * pre.spacing;
        env = glm::max(env, envelope(c, kLight, view_at(node)).value());
      }
      const glm::dvec3 want = to_xyz(spectral_srgb(c, kLight, wr));
      const glm::dvec3 got = to_xyz(evaluate_preintegrated(pre, kLight, wr));
      const glm::dvec3 bound = env * (2.0 * settings.tolerance) + storage_bound(c, pre, kLight, wr);
      for (int ch = 0; ch < 3; ++ch) {
        const double error = std::abs(got[ch] - want[ch]);
        EXPECT_LE(error, bound[ch] + 1e-12) << json << " query " << q << " channel " << ch;
        if (bound[ch] > 0) worst = std::max(worst, error / bound[ch]);
        largest_error = std::max(largest_error, error);
        peak = std::max(peak, std::abs(want[ch]));
      }
    }
    std::printf("interpolation, %s: worst |error| / bound = %.3g, largest error / peak = %.3g\n", json, worst,
                largest_error / peak);
  }
}

// Against the exact transform (no Taylor truncation) at the same wavelengths: the pre-integrated
// colour is as close as the per-wavelength path plus its interpolation budget, relative to the
// brightest colour of the queries.
TEST(Preintegrated, AgreesWithTheExactReference) {
  const Case c = make_case(kFingers);
  const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
  const ExactTransform exact(c.grating, c.tables);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double peak = 0.0, pre_error = 0.0, spectral_error = 0.0;
  for (int q = 0; q < 20; ++q) {
    const glm::dvec3 wr = view(unit(rng), unit(rng));
    const glm::dvec3 reference = integrate_linear_srgb(c.samples, [&](double l) {
      return exact.evaluate({kLight, wr, l}).brdf;
    });
    const glm::dvec3 a = evaluate_preintegrated(pre, kLight, wr), b = spectral_srgb(c, kLight, wr);
    peak = std::max(peak, max_component(glm::abs(reference)));
    pre_error = std::max(pre_error, max_component(glm::abs(a - reference)));
    spectral_error = std::max(spectral_error, max_component(glm::abs(b - reference)));
  }
  std::printf("vs exact: spectral %.3g, preintegrated %.3g (relative to peak %.3g)\n", spectral_error / peak,
              pre_error / peak, peak);
  EXPECT_LE(spectral_error, 1e-3 * peak);
  EXPECT_LE(pre_error, spectral_error + 2e-2 * peak);
}

// A tall grating over a wide range of w needs float storage (halves would lose the budget to the
// polynomial's cancellation); at the nodes it then matches the per-wavelength path to float rounding.
TEST(Preintegrated, TallGratingsStoreFloats) {
  Case c =
      make_case(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":300,"size_um":4,"samples":64,"coherence_um":2})");
  c.domain.uv_max = c.domain.uv_min + glm::dvec2(0.05, 0.05);  // a small window of the scene keeps the test fast
  const PreintegratedLayout layout = preintegrated_layout(c.tables, c.samples, c.domain, {});
  const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
  EXPECT_GT(layout.amplification / 2048.0, 1e-2 / 4);
  ASSERT_EQ(pre.words, 3);
  for (int iu = 0; iu < pre.nu; iu += 3) {
    const glm::dvec3 wr = view_at(pre.origin + glm::dvec2(iu, pre.nv / 2) * pre.spacing);
    const glm::dvec3 want = to_xyz(spectral_srgb(c, kLight, wr)), got = to_xyz(evaluate_preintegrated(pre, kLight, wr));
    const glm::dvec3 bound = storage_bound(c, pre, kLight, wr) + 1e-12 * max_component(glm::abs(want));
    for (int ch = 0; ch < 3; ++ch) EXPECT_LE(std::abs(got[ch] - want[ch]), bound[ch]) << iu << " " << ch;
  }
}

// A float evaluation of the same words agrees with the double one to float rounding: of the Horner
// sum (4 terms x eps_f of the envelope), of the cell fractions (eps_f |uv| / spacing, moving the
// interpolation weights) and of the factor and the sRGB matrix (1e-5 of the value; lavapipe's exp and
// sqrt are within a few ulp).
glm::dvec3 float_bound(const Case& c, const PreintegratedTables& pre, const glm::dvec3& wr, const glm::dvec3& want) {
  constexpr double kFloatEps = 5.96e-8;
  const double uv_rounding = 2.0 * kFloatEps * 2.0 / std::min(pre.spacing.x, pre.spacing.y);
  return envelope(c, kLight, wr).value() * (4.0 * pre.terms * kFloatEps + uv_rounding) + 1e-5 * glm::abs(want);
}

// The float twin of the kernel (what the GPU runs), on the CPU.
TEST(Preintegrated, FloatTwinMatchesDouble) {
  const Case c = make_case(kSinusoid);
  const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
  namespace f32 = kernels::f32;
  const f32::PreintegratedGrid grid(glm::vec2(pre.origin), glm::vec2(pre.spacing), pre.nu, pre.nv, pre.terms,
                                    pre.words);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int q = 0; q < 100; ++q) {
    const glm::dvec3 wr = view(unit(rng), unit(rng));
    const glm::vec3 wi_f(kLight), wr_f(wr);
    const f32::DiffractionGeometry g =
        f32::diffraction_geometry(wi_f, wr_f, float(pre.floor_lambda_nm), float(pre.sigma_nm), float(pre.hs_nm));
    const f32::PreintegratedCell cell = f32::preintegrated_cell(grid, f32::preintegrated_uv(wi_f, wr_f));
    glm::vec3 acc(0.0f);
    for (int p = pre.terms - 1; p >= 0; --p) {
      glm::vec3 t[4];
      for (int corner = 0; corner < 4; ++corner) {
        const std::uint32_t* w = &pre.packed[f32::preintegrated_word_index(grid, cell, corner % 2, corner / 2, p)];
        t[corner] = f32::preintegrated_unpack_half(w[0], w[1], pre.scale[p]);
      }
      acc = f32::preintegrated_horner_step(acc, g.w - float(pre.w_centre), cell, t[0], t[1], t[2], t[3]);
    }
    const glm::dvec3 got =
        to_xyz(glm::dvec3(f32::preintegrated_linear_srgb(g, acc, float(pre.sigma_nm), float(pre.R0))));
    const glm::dvec3 want = to_xyz(evaluate_preintegrated(pre, kLight, wr));
    const glm::dvec3 bound = float_bound(c, pre, wr, want);
    for (int ch = 0; ch < 3; ++ch) EXPECT_LE(std::abs(got[ch] - want[ch]), bound[ch]) << q;
  }
}

// The GPU (float, lavapipe) runs render/diffraction_preintegrated.glsl on the same words: within
// the float bound of the double twin, on 4096 views of the scene.
TEST(Preintegrated, GpuMatchesTheDoubleTwin) {
  const Case c = make_case(kSinusoid);
  const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  for (int q = 0; q < 4096; ++q) pairs.emplace_back(kLight, view(unit(rng), unit(rng)));
  auto context = test::make_validated_context();
  const test::ProbeRun run = test::run_preintegrated_probe(*context, pre, pairs);
  double worst = 0.0;
  for (size_t q = 0; q < pairs.size(); ++q) {
    const glm::dvec3 want = to_xyz(evaluate_preintegrated(pre, kLight, pairs[q].second)), got = to_xyz(run.rgb[q]);
    const glm::dvec3 bound = float_bound(c, pre, pairs[q].second, want);
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_LE(std::abs(got[ch] - want[ch]), bound[ch]) << q << " " << ch;
      if (bound[ch] > 0) worst = std::max(worst, std::abs(got[ch] - want[ch]) / bound[ch]);
    }
  }
  std::printf("GPU vs double twin: worst |error| / bound = %.3g\n", worst);
}

// Every direction pair, including grazing ones, pairs outside the domain (clamped to its edge) and
// both directions at z = 0, gives a finite colour.
TEST(Preintegrated, FiniteOnTheWholeDomain) {
  const Case c = make_case(kSinusoid);
  const PreintegratedTables pre = build_preintegrated_tables(c.tables, c.samples, c.domain);
  for (double ix : {-1.0, -0.7, 0.0, 0.3, 1.0})
    for (double rx : {-1.0, -0.99, -0.5, 0.0, 0.5, 1.0})
      for (double ry : {-1.0, 0.0, 1e-12}) {
        const glm::dvec3 wi = direction(ix, 0.0);
        const glm::dvec3 wr = glm::normalize(glm::dvec3(rx, ry, std::sqrt(std::max(0.0, 1 - rx * rx - ry * ry))));
        const glm::dvec3 rgb = evaluate_preintegrated(pre, wi, wr);
        for (int ch = 0; ch < 3; ++ch) EXPECT_TRUE(std::isfinite(rgb[ch])) << ix << " " << rx << " " << ry;
      }
}

// A domain the device cannot hold is refused with one line naming the sizes, before any allocation.
TEST(Preintegrated, TooLargeTablesAreRefused) {
  const Case c = make_case(kSinusoid);
  PreintegratedDomain everything{glm::dvec2(-2.0), glm::dvec2(2.0), -2.0, 0.0};
  PreintegrationSettings settings;
  settings.tolerance = 1e-4;
  settings.max_bytes = 64 << 20;
  const PreintegratedLayout layout = preintegrated_layout(c.tables, c.samples, everything, settings);
  EXPECT_GT(layout.bytes, settings.max_bytes);
  try {
    build_preintegrated_tables(c.tables, c.samples, everything, settings);
    FAIL() << "expected a refusal";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("more than the 64.0 MiB of device memory"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

}  // namespace preintegrated_test
}  // namespace facet
