// The edge term of the error estimate (docs/error_estimate.md, eqs. 3 and 3'), on images built by hand
// whose colour steps give the expected terms directly: a quarter of the step over K. Edges of coverage,
// normals, uv, depth and shadows.
#include "image/edge_error.hpp"

#include <gtest/gtest.h>

namespace facet {
namespace edge_error_test {

// A 4x1 strip: colours c[i], coverage a[i], every normal +z, texture terms t[i] (> 0: a texture term
// models the pixel; 0 here means none does).
struct Strip {
  Image image{4, 1};
  std::vector<AovPixel> pixels{4};
  Strip(const float (&c)[4], const float (&a)[4], const float (&t)[4]) {
    image.alpha.resize(4);
    for (int i = 0; i < 4; ++i) {
      image.set(i, glm::vec3(c[i]));
      image.alpha[i] = a[i];
      pixels[i].normal = glm::vec3(0, 0, 1);
      pixels[i].error = t[i];
      pixels[i].texture_term = t[i] > 0.0f;
    }
  }
};

TEST(EdgeError, CoverageEdgesTakeAQuarterOfTheStepOverK) {
  // Textured pixels (term 0.01) on both sides of a silhouette: only the two beside it have an edge term.
  Strip s({0.8f, 0.8f, 0.2f, 0.2f}, {1, 1, 0, 0}, {0.01f, 0.01f, 0, 0});
  const std::vector<float> k1 = edge_error(s.image, s.pixels, 1), k2 = edge_error(s.image, s.pixels, 2);
  EXPECT_FLOAT_EQ(k1[0], 0.0f);
  EXPECT_FLOAT_EQ(k1[1], 0.25f * 0.6f);
  EXPECT_FLOAT_EQ(k1[2], 0.25f * 0.6f);
  EXPECT_FLOAT_EQ(k1[3], 0.0f);
  EXPECT_FLOAT_EQ(k2[1], 0.125f * 0.6f);
}

TEST(EdgeError, UnestimatedPixelsTakeTheContrastOfCoveredNeighbours) {
  // Covered pixels without a texture term (e.g. a traced microsurface): each takes a quarter of its
  // largest step to a covered neighbour; the uncovered pixel takes none, the textured one none either.
  Strip s({0.1f, 0.5f, 0.3f, 0.9f}, {1, 1, 1, 0}, {0, 0, 0.02f, 0});
  const std::vector<float> e = edge_error(s.image, s.pixels, 1);
  EXPECT_FLOAT_EQ(e[0], 0.25f * 0.4f);  // |0.1 - 0.5|
  EXPECT_FLOAT_EQ(e[1], 0.25f * 0.4f);  // max(|0.5 - 0.1|, |0.5 - 0.3|)
  EXPECT_FLOAT_EQ(e[2], 0.25f * 0.6f);  // textured, but beside the silhouette to pixel 3: |0.3 - 0.9|
  EXPECT_FLOAT_EQ(e[3], 0.25f * 0.6f);  // uncovered: the silhouette only
}

TEST(EdgeError, UniformSurfacesReadZero) {
  Strip s({0.4f, 0.4f, 0.4f, 0.4f}, {1, 1, 1, 1}, {0, 0, 0, 0});
  for (float e : edge_error(s.image, s.pixels, 1)) EXPECT_EQ(e, 0.0f);
}

// A covered, textured 6x1 strip facing +z whose colours step by 0.1 per pixel, except one step of 0.5
// between pixels 2 and 3: uv and depth as given per pixel.
struct CoveredStrip {
  Image image{6, 1};
  std::vector<AovPixel> pixels{6};
  CoveredStrip(const float (&u)[6], const float (&depth)[6]) {
    image.alpha.assign(6, 1.0f);
    const float c[6] = {0.1f, 0.2f, 0.3f, 0.8f, 0.9f, 1.0f};
    for (int i = 0; i < 6; ++i) {
      image.set(i, glm::vec3(c[i]));
      pixels[i].normal = glm::vec3(0, 0, 1);
      pixels[i].uv = glm::vec2(u[i], 0.5f);
      pixels[i].depth = depth[i];
      pixels[i].error = 0.01f;
      pixels[i].texture_term = true;
    }
  }
};

TEST(EdgeError, UvSeamsAndSilhouettesOfParallelSurfacesAreEdges) {
  // Same normal everywhere. A uv seam between pixels 2 and 3 (the uv step there 10 times its
  // neighbours'); then, with uv continuous, a silhouette: the surface of pixels 3-5 nearer (1/depth
  // affine on each side, its step there 40 times theirs). Only pixels 2 and 3 take 0.5 / 4.
  const float ramp[6] = {0.10f, 0.11f, 0.12f, 0.13f, 0.14f, 0.15f};
  const float seam[6] = {0.10f, 0.11f, 0.12f, 0.22f, 0.23f, 0.24f};
  const float flat[6] = {2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f};
  const float silhouette[6] = {1 / 0.500f, 1 / 0.501f, 1 / 0.502f, 1 / 0.542f, 1 / 0.543f, 1 / 0.544f};
  for (const CoveredStrip& s : {CoveredStrip(seam, flat), CoveredStrip(ramp, silhouette)}) {
    const std::vector<float> e = edge_error(s.image, s.pixels, 1);
    for (int i : {0, 1, 4, 5}) EXPECT_EQ(e[i], 0.0f) << i;
    EXPECT_FLOAT_EQ(e[2], 0.25f * 0.5f);
    EXPECT_FLOAT_EQ(e[3], 0.25f * 0.5f);
  }
}

TEST(EdgeError, APlaneRecedingInPerspectiveHasNoEdge) {
  // One plane seen in perspective: 1/depth affine along the strip, uv (a position on the plane) its
  // inverse, so uv's steps grow 1.5-3x per pixel toward the far end; depths themselves differ by up
  // to 6x. No jump, so no edge term, whatever the colours do.
  float u[6], depth[6];
  for (int i = 0; i < 6; ++i) {
    const float inverse_depth = 0.6f - 0.1f * static_cast<float>(i);
    depth[i] = 1.0f / inverse_depth;
    u[i] = depth[i];
  }
  const CoveredStrip s(u, depth);
  for (float e : edge_error(s.image, s.pixels, 1)) EXPECT_EQ(e, 0.0f);
}

TEST(EdgeError, ShadowEdgesAreEdges) {
  // One flat textured surface (uv and depth continuous), its colours stepping by 0.1 but 0.5 between
  // pixels 2 and 3, where a shadow's edge lies when the light reaches different fractions of their hits.
  // With one ray per pixel: lit, lit, lit, shadowed, ... gives pixels 2 and 3 a quarter of the step; with
  // 2 x 2 strata, one stratum's difference (0.75 against 0.5) is an edge too, and equal fractions none.
  const float u[6] = {0.10f, 0.11f, 0.12f, 0.13f, 0.14f, 0.15f};
  const float depth[6] = {2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f};
  CoveredStrip s(u, depth);
  for (const float lit_far_side : {0.0f, 1.0f}) {
    for (int i = 3; i < 6; ++i) s.pixels[i].lit = lit_far_side;
    const std::vector<float> e = edge_error(s.image, s.pixels, 1);
    for (int i : {0, 1, 4, 5}) EXPECT_EQ(e[i], 0.0f) << i;
    EXPECT_FLOAT_EQ(e[2], lit_far_side == 0.0f ? 0.25f * 0.5f : 0.0f);
    EXPECT_FLOAT_EQ(e[3], lit_far_side == 0.0f ? 0.25f * 0.5f : 0.0f);
  }
  for (int i = 0; i < 6; ++i) s.pixels[i].lit = i < 3 ? 0.75f : 0.5f;
  const std::vector<float> k2 = edge_error(s.image, s.pixels, 2);
  EXPECT_FLOAT_EQ(k2[2], 0.125f * 0.5f);
  EXPECT_FLOAT_EQ(k2[3], 0.125f * 0.5f);
  EXPECT_EQ(k2[1], 0.0f);
}

}  // namespace edge_error_test
}  // namespace facet
