// CPU material shading pieces: the bilinear texture sampler and the microsurface albedo.
#include <gtest/gtest.h>

#include <cmath>

#include "cpu/material_shading.hpp"

namespace facet {
namespace {

const assets::ScalarField kField{3, 2, {0.0, 1.0, 5.0, 2.0, -3.0, 7.0}};

TEST(MaterialShading, BilinearHitsTexelCentresAndWraps) {
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      const glm::dvec2 uv((i + 0.5) / 3.0, (j + 0.5) / 2.0);
      // (i + 1/2)/3 · 3 − 1/2 rounds to i within 1 ulp of 3: the weights are exact to ~1e-15.
      EXPECT_NEAR(cpu::sample_bilinear(kField, uv), kField.at(i, j), 1e-14);
      EXPECT_NEAR(cpu::sample_bilinear(kField, uv + glm::dvec2(-2.0, 3.0)), kField.at(i, j), 1e-13);
    }
  }
  // Halfway between the centres of texels (2, 1) and (0, 1) across the wrap: (7 + 2)/2.
  EXPECT_NEAR(cpu::sample_bilinear(kField, {1.0, 0.75}), 4.5, 1e-14);
  EXPECT_NEAR(cpu::sample_bilinear(kField, {0.0, 0.75}), 4.5, 1e-14);
}

TEST(MaterialShading, BilinearMeanOverATileIsTheTexelMean) {
  // Midpoint rule on a 300×200 grid aligned with the texels: exact for a bilinear function per cell.
  double sum = 0.0;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 300; ++i) sum += cpu::sample_bilinear(kField, {(i + 0.5) / 300.0, (j + 0.5) / 200.0});
  EXPECT_NEAR(sum / 60000.0, 12.0 / 6.0, 1e-12);
}

TEST(MaterialShading, MicrosurfaceAlbedoIsTheProductOfTheGivenMaps) {
  MicrosurfaceMaterial m;
  m.height_colormap =
      Colormap({0.0, 1.0}, {glm::dvec3(0.0), glm::dvec3(1.0, 0.5, 0.25)}, Colormap::Interpolation::Linear);
  EXPECT_EQ(cpu::microsurface_albedo(m, 0.5, {3.0, 4.0}), glm::dvec3(0.5, 0.25, 0.125));
  m.slope_colormap = Colormap({0.0, 10.0}, {glm::dvec3(0.0), glm::dvec3(1.0)}, Colormap::Interpolation::Linear);
  // |slope| = 5 -> 0.5.
  EXPECT_EQ(cpu::microsurface_albedo(m, 0.5, {3.0, 4.0}), glm::dvec3(0.25, 0.125, 0.0625));
  m.height_colormap.reset();
  EXPECT_EQ(cpu::microsurface_albedo(m, 0.5, {3.0, 4.0}), glm::dvec3(0.5));
}

}  // namespace
}  // namespace facet
