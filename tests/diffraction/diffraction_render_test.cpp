// Diffraction materials rendered: the GPU pass (float) against its CPU twin (double, same Taylor
// tables and wavelength samples), the twin against the exact reference (Chebyshev-interpolated
// exact transform, one stratified wavelength per sample), the colour bands of a plate against the
// grating equation, and scenes that do not use the material.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "common/error.hpp"
#include "cpu/diffraction_shading.hpp"
#include "cpu/direct_cpu.hpp"
#include "cpu/reference_renderer.hpp"
#include "diffraction/cie_tables.hpp"
#include "diffraction_cases.hpp"
#include "gpu/direct_pass.hpp"
#include "kernels/shared.hpp"
#include "plate_scene.hpp"
#include "scene/camera_frame.hpp"
#include "support/frame_difference.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

constexpr double kPeriodNm = 1600.0;

using test::plate_scene;  // period kPeriodNm

double largest(glm::dvec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

TEST(DiffractionRender, GpuMatchesTheDoubleTwin) {
  // Camera looking down at the plate, seeing orders -2..2 across the image; the middle of the 25
  // rows looks along v = 0, where the orders peak.
  Scene scene = plate_scene(8.0);
  scene.camera.position = {0.0, 0.0, 1.0};
  scene.camera.target = {0.0, 0.0, 0.0};
  scene.camera.fov_y_deg = 90.0;
  scene.camera.width = 48;
  scene.camera.height = 25;
  scene.ambient = {0.1, 0.1, 0.1};
  std::get<DiffractionMaterial>(scene.materials[0]).base_albedo = {0.2, 0.1, 0.05};
  auto context = test::make_validated_context();
  const Image gpu = gpu::render_direct(*context, scene, scene.camera.width, scene.camera.height);
  const Image cpu = cpu::render_direct_cpu(scene, scene.camera.width, scene.camera.height);
  // Float rays are off by ~eps = 1.2e-7 rad and the BRDF changes by k sigma (= 2 pi 8000 / 360 = 140 at
  // 360 nm) relative per radian on a peak's flank: ~2e-5; the window argument sigma k u (<= 280) is
  // rounded to ~3e-5 and each Taylor sum to ~eps e^x (docs/diffraction.md), all relative to the
  // peak's value. Tolerance: 1e-4 of the image's peak (measured 4e-6).
  const double peak = test::peak_component(cpu);
  ASSERT_GT(peak, 1.0);  // the orders are there
  double worst = 0.0;
  for (size_t i = 0; i < cpu.pixel_count(); ++i)
    worst = std::max(worst, largest(glm::dvec3(gpu.at(i)) - glm::dvec3(cpu.at(i))));
  std::cout << "[ measured ] max |gpu - cpu| = " << worst << " of peak " << peak << "\n";
  EXPECT_LE(worst, 1e-4 * peak);
}

// The dominant wavelength of a linear sRGB colour: the spectral-locus hue (around D65 white) nearest
// to the colour's, on a 0.25 nm grid of 400..700 nm.
double dominant_wavelength(glm::dvec3 rgb) {
  const glm::dmat3 to_srgb = glm::transpose(glm::dmat3(3.2409699419045213, -1.5373831775700935, -0.49861076029300327,
                                                       -0.96924363628087984, 1.8759675015077206, 0.041555057407175612,
                                                       0.055630079696993608, -0.20397695888897657, 1.0569715142428786));
  const glm::dvec3 xyz = glm::inverse(to_srgb) * rgb;
  const glm::dvec2 white(0.3127, 0.3290);
  const auto hue = [&](glm::dvec3 c) {
    const glm::dvec2 xy = glm::dvec2(c.x, c.y) / (c.x + c.y + c.z) - white;
    return std::atan2(xy.y, xy.x);
  };
  const double target = hue(xyz);
  double best = 0.0, best_distance = 1e9;
  for (double l = 400.0; l <= 700.0; l += 0.25) {
    const double distance = std::abs(std::remainder(hue(diffraction::cie_cmf(l)) - target, 2 * test::kPi));
    if (distance < best_distance) best_distance = distance, best = l;
  }
  return best;
}

TEST(DiffractionRender, PlateColoursFollowTheGratingEquation) {
  // One row of pixels across the plate; each pixel centre's ray has its own d.x, and the first
  // order there is lambda = period |d.x| (m = +-1). sigma = 20 um keeps each order's spectral
  // width s = lambda / (sqrt 2 k sigma |u|) near 4 nm, so its hue is that of one wavelength.
  Scene scene = plate_scene(20.0);
  scene.camera.position = {0.0, 0.0, 1.0};
  scene.camera.target = {0.0, 0.0, 0.0};
  scene.camera.up = {0.0, 1.0, 0.0};
  scene.camera.width = 96;
  scene.camera.height = 2;
  scene.camera.fov_y_deg = 2.0 * std::atan(std::tan(test::kPi / 6) * 2 / 96) * 180 / test::kPi;  // +-30 deg across
  auto context = test::make_validated_context();
  const Image image = gpu::render_direct(*context, scene, scene.camera.width, scene.camera.height);
  const CameraFrame frame = camera_frame(scene.camera, scene.camera.width, scene.camera.height);
  int checked = 0;
  double worst = 0.0;
  for (int x = 0; x < scene.camera.width; ++x) {
    const glm::dvec3 d =
        kernels::f64::camera_ray_direction(frame.forward, frame.right, frame.up, glm::dvec2(x + 0.5, 0.5),
                                           glm::dvec2(scene.camera.width, scene.camera.height));
    const double predicted = kPeriodNm * std::abs(d.x);    // grating equation, first order
    if (predicted < 450.0 || predicted > 630.0) continue;  // where the observer sees hue well
    const double measured = dominant_wavelength(glm::dvec3(image.at(x, 0)));
    worst = std::max(worst, std::abs(measured - predicted));
    ++checked;
  }
  std::cout << "[ measured ] " << checked << " columns, worst |dominant - grating equation| = " << worst << " nm\n";
  EXPECT_GE(checked, 20);
  // Each order is a Gaussian of s ~ 4 nm in wavelength: the observer's and D65's slopes across it
  // shift its hue by a fraction of s. 3 nm is less than a fifth of a column (16.7 nm apart).
  EXPECT_LE(worst, 3.0);
}

TEST(DiffractionRender, ExactReferenceAgreesWithTheTaylorTwinWithinTheStratificationBound) {
  // A camera far away with a tiny field of view: every sample of every pixel sees the plate from
  // the same direction (d.x = 0.35: the first order at 560 nm) to 1e-5 rad, so the pixel is one
  // integral over wavelength. The reference estimates it with one wavelength per sample from N^2
  // strata: each stratum's sample lies within the stratum's oscillation, so the error is at most
  // TV(g) / N^2, g(u) = the radiance at wavelength 360 + 470 u weighted as radiance_at does.
  Scene scene = plate_scene(8.0);
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.35, 0.0, -std::sqrt(1 - 0.35 * 0.35)));
  scene.camera.position = -10.0 * view;
  scene.camera.target = {0.0, 0.0, 0.0};
  scene.camera.fov_y_deg = 1e-4;
  scene.camera.width = 3;
  scene.camera.height = 2;
  auto& m = std::get<DiffractionMaterial>(scene.materials[0]);
  m.tolerance = 1e-9;    // Taylor and window errors far below the bound
  m.wavelengths = 1881;  // 0.25 nm: the twin's trapezoid sum is the integral to ~1e-6
  const int grid = 32;
  const Image twin = cpu::render_direct_cpu(scene, 3, 2);
  cpu::ReferenceOptions options;
  options.width = 3;
  options.height = 2;
  options.grid = grid;
  options.seed = 7;
  const Image reference = cpu::render_reference(scene, options);

  const cpu::DiffractionShading taylor(scene, cpu::DiffractionShading::Transform::Taylor);
  glm::dvec3 total_variation(0.0), previous(0.0);
  const int steps = 20000;
  for (int i = 0; i <= steps; ++i) {
    const glm::dvec3 g =
        taylor.radiance_at(0, {0, 0, 1}, false, {0, 1, 0}, -view, 1.0, double(i) / steps * (1 - 1e-12));
    if (i > 0) total_variation += glm::abs(g - previous);
    previous = g;
  }
  // Slack 1e-4 of the peak: the twin's 0.25 nm trapezoid sum and 1e-9 Taylor tolerance, and the
  // 1.7e-6 rad spread of the rays (the BRDF changes by k sigma = 140 per radian, relative), are all below it.
  const double peak = test::peak_component(twin);
  ASSERT_GT(peak, 0.05);
  const glm::dvec3 bound = total_variation / double(grid * grid) + glm::dvec3(1e-4 * peak);
  for (size_t i = 0; i < twin.pixel_count(); ++i) {
    const glm::dvec3 error = glm::abs(glm::dvec3(reference.at(i)) - glm::dvec3(twin.at(i)));
    std::cout << "[ measured ] pixel " << i << ": twin max " << largest(twin.at(i)) << ", |ref - twin| " << error.x
              << " " << error.y << " " << error.z << ", bound " << bound.x << " " << bound.y << " " << bound.z << "\n";
    for (int c = 0; c < 3; ++c) EXPECT_LE(error[c], bound[c]) << "pixel " << i << " channel " << c;
  }
}

TEST(DiffractionRender, ExactAndTaylorShadingAgreeAtATightTolerance) {
  // The same wavelength samples, P from the Taylor tables at tolerance 1e-9 or from the exact
  // transform: |S_taylor - S_exact| <= 2 W 1e-9 (Taylor remainder and window truncation; W <= 9 here),
  // so the radiance (quadratic in S) differs by ~4e-8 relative at most; 1e-6 of the peak is the bound.
  Scene scene = plate_scene(8.0);
  auto& m = std::get<DiffractionMaterial>(scene.materials[0]);
  m.tolerance = 1e-9;
  m.wavelengths = 95;
  const cpu::DiffractionShading taylor(scene, cpu::DiffractionShading::Transform::Taylor);
  const cpu::DiffractionShading exact(scene, cpu::DiffractionShading::Transform::Exact);
  std::vector<glm::dvec3> a, b;
  double peak = 0.0;
  for (double vx = -0.9; vx <= 0.9; vx += 0.01)
    for (double vy : {0.0, 0.002, 0.3}) {
      const glm::dvec3 v = test::direction(vx, vy);
      a.push_back(taylor.radiance(0, {0, 0, 1}, false, {0, 1, 0}, v, 1.0));
      b.push_back(exact.radiance(0, {0, 0, 1}, false, {0, 1, 0}, v, 1.0));
      peak = std::max(peak, largest(b.back()));
    }
  ASSERT_GT(peak, 1.0);
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, largest(a[i] - b[i]));
  std::cout << "[ measured ] max |taylor - exact| = " << worst << " of peak " << peak << "\n";
  EXPECT_LE(worst, 1e-6 * peak);
}

TEST(DiffractionRender, RefusesWorkBeyondLavapipesLoopLimit) {
  // 1600 wavelengths x 25 bins x 10 terms: 121 601 loop iterations per ray, past lavapipe's 65535
  // (which would end the spectral loop early and silently: found by this test's twin above at 336
  // wavelengths before the Taylor steps were unrolled).
  Scene scene = plate_scene(8.0);
  std::get<DiffractionMaterial>(scene.materials[0]).wavelengths = 1600;
  auto context = test::make_validated_context();
  try {
    gpu::DirectPass pass(*context, scene);
    FAIL() << "expected a refusal";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lavapipe ends a pixel's loops after 65535"), std::string::npos) << e.what();
  }
  // 800 fit (60 801 iterations), with ss:K too: each stratum is its own dispatch (tests/gpu/supersampling_test).
  std::get<DiffractionMaterial>(scene.materials[0]).wavelengths = 800;
  EXPECT_NO_THROW(gpu::DirectPass(*context, scene));
  EXPECT_NO_THROW(gpu::DirectPass(*context, scene, gpu::RenderMethod::parse("ss:2")));
}

TEST(DiffractionRender, UnusedDiffractionMaterialChangesNothing) {
  // A Lambert scene renders bit-identically whether or not the pass compiles the diffraction code
  // in (kHasDiffraction follows the scene's materials, not the objects).
  Scene scene;
  scene.camera.width = 24;
  scene.camera.height = 16;
  scene.light.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  scene.materials = {LambertMaterial{{0.7, 0.5, 0.3}}};
  scene.material_names = {"grey"};
  scene.planes.push_back({});
  scene.spheres.push_back({{0.0, 0.8, 0.0}, 0.8, 0});
  auto context = test::make_validated_context();
  const Image without = gpu::render_direct(*context, scene, 24, 16);
  scene.materials.push_back(plate_scene(8.0).materials[0]);
  scene.material_names.push_back("unused");
  const Image with = gpu::render_direct(*context, scene, 24, 16);
  EXPECT_EQ(without.rgb, with.rgb);
}

TEST(DiffractionRender, GrazingAndBacklitPixelsStayFinite) {
  // The horizon of an infinite plate (w -> 0) and a light below it.
  Scene scene = plate_scene(8.0);
  scene.camera.position = {0.0, -3.0, 0.2};
  scene.camera.target = {0.0, 10.0, 0.0};
  scene.light.direction = glm::normalize(glm::dvec3(0.0, 1.0, 1e-4));
  auto context = test::make_validated_context();
  for (const glm::dvec3 light : {glm::dvec3(0.0, 1.0, 1e-4), glm::dvec3(0.0, 0.0, -1.0)}) {
    scene.light.direction = glm::normalize(light);
    const Image gpu = gpu::render_direct(*context, scene, 32, 16);
    for (size_t i = 0; i < gpu.pixel_count(); ++i)
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(gpu.at(i)[c])) << i;
  }
}

}  // namespace
}  // namespace facet
