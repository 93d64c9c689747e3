// The binary and the rotated crossed grating of scenes/ (issue 20; at the scenes' full view their
// `preintegrated` tables take 258 and 218 MiB, refused while tables could not pass 128 MiB) render
// with `preintegrated` and agree with `spectral` on the same scene. The tests narrow the view and use 16
// wavelengths so that the tables build in a few seconds; both paths integrate the same samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "gpu/diffraction_fast_upload.hpp"
#include "gpu/direct_pass.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace gratings_render_test {

constexpr int kSize = 48;

Image render(vk::Context& context, const Scene& scene, diffraction::DiffractionMethod method) {
  gpu::RenderMethod m;
  m.diffraction.method = method;
  m.diffraction.wavelengths = 16;
  return gpu::render_direct(context, scene, kSize, kSize, m);
}

// A narrow view of the plate around `target`: a point the camera sees (1.64 away) offset from the
// mirror point by d leaves the mirror direction by about d / 1.64 in (u, v), so a first order of
// period P along the unit vector a (lambda / P, 0.15 to 0.35 for P = 2.4 um) shows near 1.64 (lambda / P) a.
void expect_preintegrated_agrees(const std::string& name, glm::dvec2 target) {
  auto context = test::make_validated_context();
  Scene scene = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes" / name);
  scene.camera.target = glm::dvec3(target, 0.0);
  scene.camera.fov_y_deg = 12.0;
  const Image spectral = render(*context, scene, diffraction::DiffractionMethod::Spectral);
  const Image pre = render(*context, scene, diffraction::DiffractionMethod::Preintegrated);
  double max_abs = 0.0, peak = 0.0;
  for (size_t i = 0; i < pre.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(pre.at(i)[c])) << i;
      max_abs = std::max(max_abs, static_cast<double>(std::abs(pre.at(i)[c] - spectral.at(i)[c])));
      peak = std::max(peak, static_cast<double>(spectral.at(i)[c]));
    }
  std::cout << name << ": peak " << peak << ", preintegrated max |diff| " << max_abs << " (" << max_abs / peak
            << " of the peak)\n";
  ASSERT_GT(peak, 0.2);  // orders, not just the base albedo's 0.04 / pi
  // F.6: interpolation <= tol E (2 tol E with the stated approximations), storage 2^-11 E
  // (docs/diffraction_fast_paths.md). The envelope E is taken as the brightest colour: the window
  // (coherence 2 periods and more) keeps neighbouring orders of one wavelength apart, so at a pixel one
  // order per wavelength contributes; doubled for the float GPU path.
  EXPECT_LE(max_abs, 2.0 * (2.0 * gpu::kPreintegrationTolerance + std::ldexp(1.0, -11)) * peak);
}

TEST(GratingsRender, BinaryGratingPreintegratedAgreesWithSpectral) {
  expect_preintegrated_agrees("diffraction_binary.json", {0.33, 0.0});  // first orders, lambda / P ~ 0.2
}

TEST(GratingsRender, RotatedCrossedGratingPreintegratedAgreesWithSpectral) {
  // The first orders of the 2.0 um period, along the ridges (the tangent, 30 degrees from y).
  expect_preintegrated_agrees("diffraction_crossed_rotated.json", 1.64 * 0.25 * glm::dvec2(0.5, 0.866));
}

}  // namespace gratings_render_test
}  // namespace facet
